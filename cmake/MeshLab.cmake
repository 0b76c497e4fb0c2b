# Locates the pieces of Debian's MeshLab 2020.09 the project builds against:
#  - the source package's src/common headers and vcglib (fetched by scripts/setup.sh into .deps/meshlab-src)
#  - the installed libmeshlab-common.so, meshlab and meshlabserver binaries and system plugins.
set(MESHLAB_SOURCE_DIR "${PROJECT_SOURCE_DIR}/.deps/meshlab-src" CACHE PATH
    "MeshLab source tree holding src/common and vcglib (scripts/setup.sh fetches it)")
# Debian installs MeshLab's libraries under the multiarch folder (e.g. lib/x86_64-linux-gnu).
set(QMF_LIB_ARCH_DIR "lib/${CMAKE_LIBRARY_ARCHITECTURE}")
set(MESHLAB_LIB_DIR "/usr/${QMF_LIB_ARCH_DIR}/meshlab" CACHE PATH "Installed MeshLab library folder")
set(MESHLAB_BIN_DIR "/usr/bin" CACHE PATH "Folder of the installed meshlab and meshlabserver binaries")

if(NOT EXISTS "${MESHLAB_SOURCE_DIR}/vcglib/vcg/complex/complex.h")
  message(FATAL_ERROR "vcglib not found in ${MESHLAB_SOURCE_DIR}: run scripts/setup.sh first "
                      "(or set MESHLAB_SOURCE_DIR to an unpacked 'apt-get source meshlab' tree)")
endif()

find_package(Eigen3 3.3 REQUIRED NO_MODULE)

# vcglib as a header-only target (SYSTEM: its warnings are not ours).
add_library(vcglib INTERFACE)
target_include_directories(vcglib SYSTEM INTERFACE "${MESHLAB_SOURCE_DIR}/vcglib")
target_link_libraries(vcglib INTERFACE Eigen3::Eigen)
# vcglib's PLY reader/writer is not header-only; libmeshlab-common does not export it.
set(VCG_PLYLIB_SOURCE "${MESHLAB_SOURCE_DIR}/vcglib/wrap/ply/plylib.cpp")
