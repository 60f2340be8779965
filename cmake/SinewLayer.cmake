# sinew_add_layer(NAME DEPS targets...): the library target sinew_NAME from src/NAME/*.cc.
# A layer without sources yet is an INTERFACE target, so the layer list stays fixed.
set(SINEW_LAYER_TARGETS "" CACHE INTERNAL "")
function(sinew_add_layer name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  set(target sinew_${name})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${name}/*.cc)
  if(sources)
    add_library(${target} STATIC ${sources})
    target_compile_options(${target} PRIVATE ${SINEW_WARNINGS})
    set(scope PUBLIC)
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
  endif()
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
    $<INSTALL_INTERFACE:include/sinew>)
  target_link_libraries(${target} ${scope} ${ARG_DEPS})
  add_library(sinew::${name} ALIAS ${target})
  set(SINEW_LAYER_TARGETS ${SINEW_LAYER_TARGETS} ${target} CACHE INTERNAL "")
endfunction()
