# Builds a private MeshLab prefix so tests never touch /usr (run with cmake -P):
#   STAGE/bin/{meshlab,meshlabserver}                          copies (a symlinked binary would
#                                                              resolve its plugin folder to /usr)
#   STAGE/ARCH_LIB_DIR/meshlab/libmeshlab-common.so            symlink (found through RUNPATH)
#   STAGE/ARCH_LIB_DIR/meshlab/plugins/*.so                    symlinks to the system plugins,
#                                                              except any installed copy of ours,
#                                                              plus a symlink to the freshly built plugin
# Inputs: STAGE, ARCH_LIB_DIR (the binaries' multiarch library folder, e.g. lib/x86_64-linux-gnu:
# their RUNPATH points there), MESHLAB_LIB_DIR, MESHLAB_BIN_DIR, PLUGIN (path of the built plugin .so).
foreach(var STAGE ARCH_LIB_DIR MESHLAB_LIB_DIR MESHLAB_BIN_DIR PLUGIN)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "stage_meshlab.cmake: ${var} is not set")
  endif()
endforeach()

set(lib "${STAGE}/${ARCH_LIB_DIR}/meshlab")
file(MAKE_DIRECTORY "${STAGE}/bin" "${lib}/plugins")
foreach(exe meshlab meshlabserver)
  if(EXISTS "${MESHLAB_BIN_DIR}/${exe}")
    file(COPY "${MESHLAB_BIN_DIR}/${exe}" DESTINATION "${STAGE}/bin" FOLLOW_SYMLINK_CHAIN)
  endif()
endforeach()
file(CREATE_LINK "${MESHLAB_LIB_DIR}/libmeshlab-common.so" "${lib}/libmeshlab-common.so" SYMBOLIC)

get_filename_component(ours "${PLUGIN}" NAME)
file(GLOB old_links "${lib}/plugins/*.so")
foreach(l ${old_links})
  file(REMOVE "${l}")
endforeach()
file(GLOB system_plugins "${MESHLAB_LIB_DIR}/plugins/*.so")
foreach(p ${system_plugins})
  get_filename_component(name "${p}" NAME)
  if(NOT name STREQUAL ours)           # an earlier `cmake --install` copy must not shadow the build
    file(CREATE_LINK "${p}" "${lib}/plugins/${name}" SYMBOLIC)
  endif()
endforeach()
file(CREATE_LINK "${PLUGIN}" "${lib}/plugins/${ours}" SYMBOLIC)
