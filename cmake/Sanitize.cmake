# QMF_SANITIZE: everything compiled here (core, plugin objects, tests) with AddressSanitizer and
# UndefinedBehaviorSanitizer; any report aborts the test (-fno-sanitize-recover=all). Use its own
# build tree (scripts/test.sh: build-sanitize/); tests/CMakeLists.txt then builds only the unit,
# plugin and fuzz tests, named "Sanitizer.*" and labelled "sanitizer". The installed MeshLab and Qt
# libraries are not instrumented (their leaks: tests/support/lsan_suppressions.txt).
if(NOT QMF_SANITIZE)
  return()
endif()
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  message(FATAL_ERROR "QMF_SANITIZE needs GCC or Clang")
endif()
set(QMF_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
# -O1 -g1: readable stack traces at a fraction of the RelWithDebInfo compile time.
add_compile_options(${QMF_SANITIZE_FLAGS} -O1 -g1)
add_link_options(${QMF_SANITIZE_FLAGS})
