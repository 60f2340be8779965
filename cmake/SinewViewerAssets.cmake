# Embeds the HTML viewer (web/viewer.html) and the three.js files it needs, from the npm
# package pinned in web/package-lock.json, into a generated C++ source of target sinew_viz.
set(SINEW_WEB_DIR ${PROJECT_SOURCE_DIR}/web)
set(SINEW_THREE_DIR ${SINEW_WEB_DIR}/node_modules/three)
set(SINEW_VIEWER_FILES
  ${SINEW_WEB_DIR}/viewer.html
  ${SINEW_THREE_DIR}/build/three.module.min.js
  ${SINEW_THREE_DIR}/examples/jsm/loaders/GLTFLoader.js
  ${SINEW_THREE_DIR}/examples/jsm/utils/BufferGeometryUtils.js
  ${SINEW_THREE_DIR}/examples/jsm/controls/OrbitControls.js)
foreach(f ${SINEW_VIEWER_FILES})
  if(NOT EXISTS ${f})
    message(FATAL_ERROR "Missing ${f}: the HTML viewer embeds three.js from web/node_modules. "
                        "Run scripts/setup.sh (it runs 'npm ci' in web/).")
  endif()
endforeach()
set(SINEW_VIEWER_SOURCE ${PROJECT_BINARY_DIR}/generated/viewer_assets.cc)
add_custom_command(
  OUTPUT ${SINEW_VIEWER_SOURCE}
  COMMAND ${CMAKE_COMMAND} -DOUTPUT=${SINEW_VIEWER_SOURCE} "-DFILES=${SINEW_VIEWER_FILES}"
          -P ${PROJECT_SOURCE_DIR}/cmake/EmbedFiles.cmake
  DEPENDS ${SINEW_VIEWER_FILES} ${PROJECT_SOURCE_DIR}/cmake/EmbedFiles.cmake
  COMMENT "Embedding the HTML viewer and three.js"
  VERBATIM)
target_sources(sinew_viz PRIVATE ${SINEW_VIEWER_SOURCE})
# The embedded files are string literals far longer than the 65,536 characters the standard
# promises; GCC and clang take them, but clang's -Wpedantic says so.
set_source_files_properties(${SINEW_VIEWER_SOURCE} PROPERTIES COMPILE_OPTIONS -Wno-overlength-strings)
