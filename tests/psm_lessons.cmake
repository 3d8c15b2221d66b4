# Lessons 08 and 09, perspective shadow maps (label gpu). The lessons' own headless, preset, UI,
# god-view, A/B, golden and bad-input tests come from tests/gpu.cmake; this file adds
#   gpu.psm.NAME        the nasty cases through lesson 09's --set interface (check_psm_case.cmake):
#                       no GL error, nothing non-finite, misclassified and leaked shares within bounds
#   gpu.psm.control.*   broken set-ups the same check must reject
#   gpu.psm.sweep.*     psm_bench's worst sweep directions: PSM with the fixes aliasing less than the
#                       uniform map at equal texels (check_psm_versus_uniform.cmake), and its control
#   gpu.psm.stress      a seeded GPU stress run of 240 random camera and light configurations at
#                       160x90 (tests/gpu/psm_stress.cpp); target psm_stress_soak runs 6,000
# The bounds. Against ground truth at 480x270 (~130,000 pixels, ~90,000 facing the light), a
# correct PSM errs only along shadow outlines, where a texel covers 0.2 to 2 pixels (aliasing m
# measured per case): 0.04 % to 0.6 % of the facing pixels in these views. MAX_BP = 150 (1.5 %) leaves
# room for the driver and the load. A shadow that vanishes or inverts costs far more: the city's
# shadows are ~35 % of the facing pixels (the student stubs' control below leaks all of them:
# 37 %), acne from a missing bias is 10-25 % (the second control). Leaks as a share of the truly
# shadowed pixels (MAX_LEAK_BP = 500: 5 %, the issue's "a shadow vanishes") catch a lost shadow even
# where the shadows are a small part of the frame; judged only with over 1,000 shadowed pixels.
if(SHADOWLAB_UNIT_ONLY OR NOT TARGET lesson_09_psm_fixes OR NOT TARGET lesson_08_psm)
  return()
endif()
set(psm_out ${CMAKE_BINARY_DIR}/test-screenshots/psm)
file(MAKE_DIRECTORY ${psm_out})

# psm_case(NAME ok|fail MAX_BP MAX_LEAK_BP [MIN_FACING n] [COUNTER|NO_COUNTER name] ARGS...): one
# lesson-09 run (lesson 08's for a NAME starting "original").
function(psm_case name expect max_bp max_leak_bp)
  set(args ${ARGN})
  set(min_facing 5000)
  set(counter "")
  if(args AND ARGV4 STREQUAL "MIN_FACING")
    list(GET args 1 min_facing)
    list(REMOVE_AT args 0 1)
  endif()
  list(GET args 0 first)
  if(first STREQUAL "COUNTER" OR first STREQUAL "NO_COUNTER")
    list(GET args 1 counter_name)
    set(counter "-D${first}=${counter_name}")
    list(REMOVE_AT args 0 1)
  endif()
  set(lesson $<TARGET_FILE:lesson_09_psm_fixes>)
  if(name MATCHES "^original")
    set(lesson $<TARGET_FILE:lesson_08_psm>)
  endif()
  add_test(NAME gpu.psm.${name} COMMAND ${CMAKE_COMMAND} -DLESSON=${lesson} -DOUT=${psm_out}/${name}.json
           -DNAME=${name} -DEXPECT=${expect} -DMAX_BP=${max_bp} -DMAX_LEAK_BP=${max_leak_bp} -DMIN_FACING=${min_facing}
           ${counter} "-DARGS=${args}" -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_psm_case.cmake)
  set_tests_properties(gpu.psm.${name} PROPERTIES LABELS gpu TIMEOUT 300)
endfunction()

# Cameras whose axes are exact: yaw 0 looks down -z, so "along", "against" and "perpendicular" are
# exact up to the float the parameters are parsed into, and the eye of LEVEL is exactly (0 2 40).
set(DOWN --set camera.yaw=0 --set camera.pitch=0.5 --set camera.distance=45)
set(LEVEL --set camera.yaw=0 --set camera.pitch=0 --set camera.distance=40)
set(UP --set camera.yaw=0 --set camera.pitch=-0.25 --set camera.distance=55 "--set;camera.target=0 16 0")
set(POINT --set light0.enabled=false --set light1.enabled=true --set measure.light=1)
# forward of DOWN: (0, -sin 0.5, -cos 0.5); of UP: (0, sin 0.25, -cos 0.25)
psm_case(dir_along ok 150 500 ${DOWN} "--set;light0.direction=0 -0.4794255 -0.8775826")
psm_case(dir_against ok 150 500 MIN_FACING 2000 ${UP} "--set;light0.direction=0 -0.247404 0.968912")
psm_case(dir_perpendicular ok 150 500 ${DOWN} "--set;light0.direction=0 -0.8775826 0.4794255")
psm_case(dir_perpendicular_level ok 150 500 ${DOWN} "--set;light0.direction=1 0 0")
psm_case(point_at_eye ok 150 500 ${LEVEL} ${POINT} "--set;light1.position=0 2 40")
psm_case(point_on_camera_plane ok 150 500 ${LEVEL} ${POINT} "--set;light1.position=12 2 40")
psm_case(grazing ok 150 500 ${DOWN} "--set;light0.direction=0.6 -0.017 -0.8")
psm_case(zf_zn_10 ok 150 500 ${DOWN} --set camera.near=4 --set camera.far=40)
psm_case(zf_zn_1e6 ok 150 500 ${DOWN} --set camera.near=0.01 --set camera.far=10000)
psm_case(zf_zn_1e6_depth16 ok 150 500 ${DOWN} --set camera.near=0.01 --set camera.far=10000 --set format=16)
psm_case(zf_zn_1e6_along ok 150 500 ${DOWN} --set camera.near=0.01 --set camera.far=10000
         "--set;light0.direction=0 -0.4794255 -0.8775826")
# Every switch through the same check: the face maps (the GLSL face lookup against the CPU's), the
# original's slide, LiSPSM, a point light inside the frustum (six faces), the original (lesson 08).
psm_case(faces_always ok 150 500 --set fix.faces=always)
# (Six faces share the light's texels: at map_size 2048 each gets 836^2 and a thin shadow between two
# blocks is lost, 1.9 % misclassified; at 4096, 1672^2 each, 0.5 %. This checks the faces, not the budget.)
psm_case(faces_point_inside ok 150 500 --preset faces_point_inside --set map_size=4096)
psm_case(virtual_slide ok 150 500 --set fix.inverse=false)
psm_case(lispsm ok 150 500 --set technique=lispsm)
# Issue 39's seam lines: the light where five cube-face maps meet, looking up the city's walls. The
# normal offset carried lookups across a face's edge, off its map, where the border said lit: thin
# bright lines across shadowed walls, 0.93 % misclassified; with the lookup kept on the face's edge
# texel, 0.18 %. The bound (0.4 %) is one the seams broke.
psm_case(seams_five_faces ok 40 300 --set camera.pitch=-0.2 --set camera.distance=45 "--set;camera.target=0 15 0"
         --set light0.kind=directional "--set;light0.direction=-0.553387225 0.198669329 -0.808883846")
# Issue 39's second case: the same camera with the light facing it (five face maps). Only 1,096
# pixels face the light, most of them one grazing wall, where the normal offset (a texel's world
# size, which the warp makes large there) pushed the lookup metres off the wall and out of its
# shadow: 11.1 % misclassified. Capped at bias.max world units (1 m, as the world bias is): 0.91 %.
# (The uniform map: 0.09 %; the issue's goal of uniform + 0.2 points is not reached here.)
psm_case(facing_five_faces ok 150 500 MIN_FACING 1000 --set camera.pitch=-0.2 --set camera.distance=45
         "--set;camera.target=0 15 0" --set light0.kind=directional
         "--set;light0.direction=0.553387225 -0.198669329 0.808883846")
# A near plane far nearer than the receivers (lesson 08's near_plane preset, issue 39 item 4): the
# original crowds them against z = 1 of post-projective space and loses its shadows (39 % of the
# pixels), saying so in its header; fix 2 alone (fix.clip: the near plane on the receivers) cures
# it (0.35 %), and lesson 09 holds at 0.002 (0.21 %) without the warning.
psm_case(original_near_plane fail 150 500 COUNTER "light0 post-projective depth" --preset near_plane)
psm_case(original_near_plane_clip ok 150 500 NO_COUNTER "light0 post-projective depth" --preset near_plane
         --set fix.clip=true)
psm_case(near_plane_0_002 ok 150 500 NO_COUNTER "light0 post-projective depth" --set camera.near=0.002)
psm_case(original ok 300 500 NO_COUNTER "light0 post-projective depth")  # the default view: no warning
# Controls: the same check rejects the student's stubs (the stub bias moves every caster to the
# origin: no shadow anywhere) and a map with no bias at all (acne).
psm_case(control.student_stubs fail 150 500 ${DOWN} --set impl=student)
psm_case(control.no_bias fail 150 500 --set bias=constant --set bias.constant=0 --set bias.normal_offset=0
         --set offset.factor=0)

# psm_bench's vanishing shadows: the terrain path (bench/paths/psm_terrain_orbit.path, sampled at
# 8 frames as the bench does, t = 11 k / 7; 320x180, 30,000 triangles, 2048^2 texels), frames 1, 3
# and 4 under the low sun facing the view, with the receiver plane (bias.receiver_plane): each tap
# compares against the receiver's own plane, and no texel-sized normal offset lifts the receivers
# of thin grazing shadows out of them. Frames 1 and 4 (4,723 and 1,494 truly shadowed pixels) must
# leak under 5 % of their shadow (the issue's "a shadow vanishes"). Frame 3's 1,121 are thin shadows
# on the far hills a texel or less wide, which every technique at 2048^2 loses in part (the uniform
# map 19 %, LiSPSM 21 %, psm_bench 2026-12-01); its bound is 25 %, where the normal offset loses all
# of them (the control). Misclassified: 1.5 % as above, 4.5 % on frame 3, whose smooth-shaded
# terminator band (facets facing away from the sun, normals facing it: ~3 % of the facing pixels,
# which the map cannot tell from shadow) counts as false shadow.
function(psm_terrain_frame name expect max_bp max_leak_bp t)
  add_test(NAME gpu.psm.${name} COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_09_psm_fixes>
           -DOUT=${psm_out}/${name}.json -DNAME=${name} -DEXPECT=${expect} -DMAX_BP=${max_bp} -DMAX_LEAK_BP=${max_leak_bp}
           -DMIN_FACING=20000 -DSIZE=320x180 "-DARGS=--set;scene=terrain;--set;triangles=30000;--set;map_size=2048;--set;technique=psm;--replay;${CMAKE_SOURCE_DIR}/bench/paths/psm_terrain_orbit.path@${t};${ARGN}"
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_psm_case.cmake)
  set_tests_properties(gpu.psm.${name} PROPERTIES LABELS gpu TIMEOUT 300)
endfunction()
set(plane --set bias.receiver_plane=true)
psm_terrain_frame(terrain_frame1 ok 150 500 1.571429 ${plane})
psm_terrain_frame(terrain_frame3 ok 450 2500 4.714286 ${plane})
psm_terrain_frame(terrain_frame4 ok 150 500 6.285714 ${plane})
# Controls: the same frames with the normal offset (bias.receiver_plane=false, the default) lose
# their shadows: frame 4 half of it, frame 3 all.
psm_terrain_frame(control.terrain_frame3_offset fail 450 2500 4.714286)
psm_terrain_frame(control.terrain_frame4_offset fail 150 500 6.285714)

# The light sweep's directions where the warp aliased more than the uniform map (1.55x and 1.11x
# before fix.fallback); the control turns the fall back off and must alias more again.
function(psm_sweep name expect t)
  add_test(NAME gpu.psm.sweep.${name} COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_09_psm_fixes>
           -DPATH_FILE=${CMAKE_SOURCE_DIR}/bench/paths/psm_light_sweep.path -DT=${t} -DOUT_DIR=${psm_out}
           -DNAME=sweep_${name} -DEXPECT=${expect} "-DARGS=${ARGN}" -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_psm_versus_uniform.cmake)
  set_tests_properties(gpu.psm.sweep.${name} PROPERTIES LABELS gpu TIMEOUT 300)
endfunction()
psm_sweep(direction_12 ok 12)
psm_sweep(direction_17 ok 17)
psm_sweep(control.no_fallback fail 12 --set fix.fallback=false)

# Issue 39's third case: the street-level view where the warp lost to the uniform map (2.49 % against
# 0.46 % misclassified) and the fall-back, predicting from the receiver volumes, never noticed. Its
# prediction now looks at the surfaces the camera sees, falls back, and is checked against what the
# drawn map measures (check_psm_fallback.cmake); the control keeps the warp.
set(STREET --set camera.yaw=0.6 --set camera.pitch=0.15 --set camera.distance=45 "--set;camera.target=0 2 0"
           --set camera.near=1 --set camera.far=1000 --set camera.fov=0.5235988 --set light0.kind=directional
           "--set;light0.direction=-0.483513441 -0.516449149 -0.706749623")
function(psm_fallback name expect)
  add_test(NAME gpu.psm.${name} COMMAND ${CMAKE_COMMAND} -DLESSON=$<TARGET_FILE:lesson_09_psm_fixes> -DOUT_DIR=${psm_out}
           -DNAME=${name} -DEXPECT=${expect} "-DVIEW=${STREET}" "-DARGS=${ARGN}"
           -P ${CMAKE_CURRENT_SOURCE_DIR}/gpu/check_psm_fallback.cmake)
  set_tests_properties(gpu.psm.${name} PROPERTIES LABELS gpu TIMEOUT 300)
endfunction()
psm_fallback(street_fallback ok)
psm_fallback(control.street_no_fallback fail --set fix.fallback=false)

# The GPU stress run: 240 seeded configurations in six lesson processes (a process per scene, light
# kind and Zf/Zn from 10 to 1e6), each configuration a frame of a generated path. Bounds at 160x90
# (~14,000 pixels): 4 % misclassified away from shadow boundaries, 25 % of the shadow leaked (the
# worst cases of a random camera are grazing outlines at m of 10 or more: see the printed worst five).
add_executable(psm_stress ${CMAKE_CURRENT_SOURCE_DIR}/gpu/psm_stress.cpp)
target_link_libraries(psm_stress PRIVATE shadowlab_measure nlohmann_json::nlohmann_json)
add_test(NAME gpu.psm.stress COMMAND psm_stress $<TARGET_FILE:lesson_09_psm_fixes> --out ${psm_out}/stress
         --configs 240 --size 160x90)
set_tests_properties(gpu.psm.stress PROPERTIES LABELS gpu TIMEOUT 900)
# Its control: the same run with the bias and normal offset off (acne everywhere) must fail.
add_test(NAME gpu.psm.stress_control COMMAND psm_stress $<TARGET_FILE:lesson_09_psm_fixes> --out ${psm_out}/stress_control
         --configs 24 --size 160x90 --set bias=constant --set bias.constant=0 --set bias.normal_offset=0 --set offset.factor=0)
set_tests_properties(gpu.psm.stress_control PROPERTIES LABELS gpu TIMEOUT 300 WILL_FAIL TRUE)
add_custom_target(psm_stress_soak
  COMMAND psm_stress $<TARGET_FILE:lesson_09_psm_fixes> --out ${CMAKE_BINARY_DIR}/psm_stress_soak --configs 6000 --size 240x135
  DEPENDS psm_stress lesson_09_psm_fixes USES_TERMINAL
  COMMENT "PSM GPU stress soak: 6,000 configurations through lesson 09")
