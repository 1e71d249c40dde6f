# Compiler warnings and sanitizers, applied to voxmod's own targets through voxmod_target_options().
add_library(voxmod_options INTERFACE)
target_compile_options(voxmod_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion-null
  -Wnon-virtual-dtor -Woverloaded-virtual -Wimplicit-fallthrough)
# RelWithDebInfo, the default build, keeps line tables only (-g1: the functions, files and lines that perf, gdb's
# backtraces and the sanitizers' reports show; no variables): full -g costs a third more build time. The level of
# debug information never changes the code generated, so the build's speed is the same.
target_compile_options(voxmod_options INTERFACE $<$<CONFIG:RelWithDebInfo>:-g1>)
if(VOXMOD_WERROR)
  target_compile_options(voxmod_options INTERFACE -Werror)
endif()
if(VOXMOD_SANITIZE)
  target_compile_options(voxmod_options INTERFACE -fsanitize=${VOXMOD_SANITIZE} -fno-omit-frame-pointer
    -fno-sanitize-recover=all)
  target_link_options(voxmod_options INTERFACE -fsanitize=${VOXMOD_SANITIZE})
endif()
# VOXMOD_TEST_CXX_FLAGS: flags for the test code alone (targets with the VOXMOD_TEST property), after all the above.
# CI's ASan + UBSan build passes -fno-sanitize=undefined: voxmod's own code keeps UBSan, the tests' gtest-heavy code
# (UBSan's checks nearly double its compile time) keeps AddressSanitizer.
target_compile_options(voxmod_options INTERFACE
  "$<$<BOOL:$<TARGET_PROPERTY:VOXMOD_TEST>>:${VOXMOD_TEST_CXX_FLAGS}>")
if(VOXMOD_BUILD_FUZZ)
  # Coverage instrumentation for every library the fuzz targets link; the targets add -fsanitize=fuzzer.
  target_compile_options(voxmod_options INTERFACE -fsanitize=fuzzer-no-link)
endif()
