# voxmod_module(NAME DEPS <voxmod modules> LIBS <external targets>)
# A module is a static library built from src/<name>/*.cpp with public headers in include/vox/<name>/.
# Dependencies are PRIVATE, so a module cannot use one it did not declare (docs/architecture.md,
# "Modules"); cmake/CheckLayering.cmake checks the includes against the same table.
function(voxmod_module name)
  cmake_parse_arguments(M "" "" "DEPS;LIBS" ${ARGN})
  file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${name}/*.cpp)
  file(GLOB_RECURSE hdrs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/include/vox/${name}/*.h
                                           ${PROJECT_SOURCE_DIR}/src/${name}/*.h)
  if(NOT srcs)  # a module whose sources have not been written yet: headers only
    add_library(vox_${name} INTERFACE)
    target_include_directories(vox_${name} INTERFACE ${PROJECT_SOURCE_DIR}/include)
    return()
  endif()
  add_library(vox_${name} STATIC ${srcs} ${hdrs})
  target_include_directories(vox_${name} PUBLIC ${PROJECT_SOURCE_DIR}/include
                                         PRIVATE ${PROJECT_SOURCE_DIR}/src)
  set(deps)
  foreach(d IN LISTS M_DEPS)
    list(APPEND deps vox_${d})
  endforeach()
  target_link_libraries(vox_${name} PUBLIC glm::glm PRIVATE ${deps} ${M_LIBS} voxmod_options)
endfunction()
