# sinew_add_layer(NAME [DEPS layers...] [PUBLIC targets...] [PRIVATE targets...]): the library
# target sinew_NAME from src/sinew/NAME/**.cc.
#   DEPS     the Sinew layers NAME uses (their short names); the only layers it may include
#            from, directly or through them (checked by the `layering` test).
#   PUBLIC   outside libraries that NAME's public headers include (users need them too).
#   PRIVATE  outside libraries used only inside NAME's .cc files and internal/ headers.
# A layer without sources is an INTERFACE target, so the layer list stays fixed.
set(SINEW_LAYER_TARGETS "" CACHE INTERNAL "")
set(SINEW_LAYER_GRAPH "" CACHE INTERNAL "")
function(sinew_add_layer name)
  cmake_parse_arguments(ARG "" "" "DEPS;PUBLIC;PRIVATE" ${ARGN})
  set(target sinew_${name})
  set(dep_targets "")
  foreach(dep ${ARG_DEPS})
    if(NOT TARGET sinew_${dep})
      message(FATAL_ERROR "layer ${name}: layer ${dep} must be added before it")
    endif()
    list(APPEND dep_targets sinew_${dep})
  endforeach()
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/sinew/${name}/*.cc)
  if(sources)
    add_library(${target} STATIC ${sources})
    target_compile_options(${target} PRIVATE ${SINEW_WARNINGS})
    target_link_libraries(${target} PUBLIC ${dep_targets} ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
    set(scope PUBLIC)
  else()
    add_library(${target} INTERFACE)
    target_link_libraries(${target} INTERFACE ${dep_targets} ${ARG_PUBLIC})
    set(scope INTERFACE)
  endif()
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
    $<INSTALL_INTERFACE:include>)
  add_library(sinew::${name} ALIAS ${target})
  set(SINEW_LAYER_TARGETS ${SINEW_LAYER_TARGETS} ${target} CACHE INTERNAL "")
  # "name:dep1,dep2" entries for cmake/CheckLayers.cmake.
  string(REPLACE ";" "," deps_csv "${ARG_DEPS}")
  set(SINEW_LAYER_GRAPH ${SINEW_LAYER_GRAPH} "${name}:${deps_csv}" CACHE INTERNAL "")
endfunction()
