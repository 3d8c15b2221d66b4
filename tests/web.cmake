# The lessons in the browser (label: web): the browser build (tools/wasm/build.sh, emscripten) in
# <build>/web, then each web lesson's page in headless Chromium against the same lesson of THIS
# build (tools/wasm/check.mjs): the default view and presets rendered, each picture within a bound
# of the native one, no WebGL error, a bad URL parameter shown on the page, a browser without
# WebGL2 told so. Needs emscripten, node, the npm packages and /usr/bin/chromium (make test
# installs them). Emscripten's system libraries are cached outside the build (tools/wasm/build.sh).
#   web.build         the pages (fixture)
#   web.NN_name       one lesson's page
#   web.shaders_es    every shader variant the web lessons compile, valid GLSL ES 3.00 (glslang)

if(NOT TARGET lesson_01_lighting)
  return()
endif()
find_program(NODE node)
find_program(EMCMAKE emcmake)
if(NOT NODE OR NOT EMCMAKE)
  message(WARNING "web tests: node or emscripten missing (make deps installs them); web tests not registered")
  return()
endif()

set(WEB_BUILD ${CMAKE_BINARY_DIR}/web)
add_test(NAME web.build COMMAND bash ${CMAKE_SOURCE_DIR}/tools/wasm/build.sh ${WEB_BUILD})
set_tests_properties(web.build PROPERTIES LABELS web FIXTURES_SETUP web_site TIMEOUT 2700
                     ENVIRONMENT "SHADOWLAB_BIN=$<TARGET_FILE_DIR:lesson_01_lighting>")
if(TEST slides.build)  # the site's decks: the ones the slide tests built and checked (tools/wasm/build.sh)
  set_tests_properties(web.build PROPERTIES FIXTURES_REQUIRED slides_built
                       ENVIRONMENT "SHADOWLAB_BIN=$<TARGET_FILE_DIR:lesson_01_lighting>;SHADOWLAB_SLIDES=${CMAKE_BINARY_DIR}/slides")
endif()

# Three presets a lesson or more. NAME:BOUND where the two rasterisers (llvmpipe natively,
# SwiftShader in Chromium) draw an implementation-defined picture: acne's stripes come from depth
# rounding, nearest-filtered moire from texel-centre rounding; their own bound is what they showed.
# (Minified without mips, bilinear_no_mips differs in 13 % of pixels for the same reason: left out.)
set(web_presets_01_lighting three_lights spot_only view_normals)
set(web_presets_02_shadow_maps acne:8 peter_pan view_map low_resolution)
set(web_presets_03_shadow_quality acne:4 slope_bias res_256 peter_pan)
# The wireframe (WEBGL_polygon_mode in the page): which pixels a one-pixel line covers is the
# rasteriser's (the GL and GL ES specifications let it deviate from the diamond-exit rule); 1.9 % measured.
set(web_presets_04_shadow_volumes camera_in_volume_zfail many_lights stencil_heatmap wireframe:3)
set(web_presets_06_texture_filtering moire_nearest:7 trilinear nearest_mipmap_nearest lod_bias_blur)
foreach(lesson IN ITEMS 01_lighting 02_shadow_maps 03_shadow_quality 04_shadow_volumes 06_texture_filtering)
  list(JOIN web_presets_${lesson} "," presets)
  add_test(NAME web.${lesson}
           COMMAND ${NODE} ${CMAKE_SOURCE_DIR}/tools/wasm/check.mjs --site ${WEB_BUILD}/site
                   --bin $<TARGET_FILE_DIR:lesson_01_lighting> --lesson ${lesson} --presets ${presets}
                   --out ${CMAKE_BINARY_DIR}/web-check/${lesson})
  set_tests_properties(web.${lesson} PROPERTIES LABELS web FIXTURES_REQUIRED web_site TIMEOUT 900)
endforeach()

# The shaders as WebGL2 compiles them, from the variants the native lessons record (shaders.cmake):
# glslang in ES mode finds what GLSL ES 3.00 refuses without a browser.
if(TARGET shader_check)
  set(es_logs "")
  foreach(lesson IN ITEMS 01_lighting 02_shadow_maps 03_shadow_quality 04_shadow_volumes 06_texture_filtering)
    list(APPEND es_logs --variants ${CMAKE_CURRENT_BINARY_DIR}/shader_variants/${lesson}.log)
  endforeach()
  add_test(NAME web.shaders_es COMMAND shader_check --es ${es_logs})
  set_tests_properties(web.shaders_es PROPERTIES LABELS "web;gpu" FIXTURES_REQUIRED shader_variants)
  # The fallbacks of the programs with a geometry stage (left out above), which no native run builds.
  add_test(NAME web.shaders_es_fallbacks COMMAND shader_check --es ${CMAKE_SOURCE_DIR}/shaders/common/lines_quad.vert)
  set_tests_properties(web.shaders_es_fallbacks PROPERTIES LABELS "web;unit")
endif()

# The browser's fallbacks, run natively: the same lessons with what WebGL2 lacks hidden from
# gl::caps() (geometry shaders: the god view's lines and gizmos as quads from lines_quad.vert, the
# volumes' silhouettes on the CPU; border clamp: clamp to edge and the shaders' range test; depth
# clamp: the infinite far plane), each preset against the golden image the normal context recorded.
set(web_hidden "GL_ARB_geometry_shader4,GL_ARB_texture_border_clamp,GL_ARB_depth_clamp")
# Where a fallback draws differently, its bound (measured: 1.30 % of pixels, RMSE 1.72): the border
# colour painted by lesson 06's shader meets the texture without the filter's blend across the edge.
set(web_bounds_06_texture_filtering --bound wrap_modes=2,2.5)
foreach(lesson IN ITEMS 02_shadow_maps 03_shadow_quality 04_shadow_volumes 06_texture_filtering)
  if(NOT TARGET lesson_${lesson} OR NOT EXISTS ${CMAKE_SOURCE_DIR}/tests/data/golden/${lesson})
    continue()
  endif()
  set(shot ${CMAKE_BINARY_DIR}/web-check/fallbacks_${lesson}.png)
  add_test(NAME web.fallbacks_native.${lesson}
           COMMAND lesson_check $<TARGET_FILE:lesson_${lesson}> --all-presets --png ${shot}
                   --golden ${CMAKE_SOURCE_DIR}/tests/data/golden/${lesson} ${web_bounds_${lesson}}
                   -- --headless --strict-gl --frames 2 --size 320x180 --screenshot ${shot})
  set_tests_properties(web.fallbacks_native.${lesson} PROPERTIES LABELS "web;gpu"
                       ENVIRONMENT "SHADOWLAB_GL_HIDE=${web_hidden}")
endforeach()
