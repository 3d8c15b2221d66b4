# The fly camera's keys and the parameters' hotkeys, headless through --keys: each step goes through
# the window's own key handler (app/input's pressKey) and, while held, the fly keys' state. Lesson 03:
#   W*5   in orbit mode W is a fly key only: the eye must not move
#   Tab   fly mode on
#   W*10  forward along the view: 10 frames of 1/60 s at half the camera distance (45 m) a second,
#         3.75 m (app/input's applyFlyKeys), straight along the forward vector
#   Home  back to the eye the run started with
#   B, B  cull_front toggles on, then off; P steps filter to its next choice
# Then --keys B must draw what --set cull_front=true draws (the hotkey drives the parameter, not a copy).
# Run: cmake -DLESSON=... -DOUT_DIR=... -P this
file(MAKE_DIRECTORY ${OUT_DIR})
set(steps "W*5,Tab,W*10,Home,B,B,P")
execute_process(COMMAND ${LESSON} --headless --frames 20 --size 320x180 --strict-gl --keys ${steps}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--keys ${steps}: exited ${rc}: ${err}")
endif()

set(num "-?[0-9]+\\.[0-9][0-9][0-9][0-9]")
# The step's report: values_N (eye then forward, as integers in 1e-4 units), camera_N, the rest.
function(step_report index step)
  string(REPLACE "*" "\\*" pattern "${step}")
  if(NOT err MATCHES "--keys ${pattern}: (eye ${num} ${num} ${num}, forward ${num} ${num} ${num}), camera ([a-z]+)([^\n]*)")
    message(FATAL_ERROR "no report of step ${step}: ${err}")
  endif()
  set(camera_${index} ${CMAKE_MATCH_2} PARENT_SCOPE)
  set(rest_${index} "${CMAKE_MATCH_3}" PARENT_SCOPE)
  string(REGEX MATCHALL "${num}" numbers "${CMAKE_MATCH_1}")
  set(values)
  foreach(n IN LISTS numbers)
    string(REPLACE "." "" v "${n}")  # four decimals: the digits are the value in 1e-4
    string(REGEX REPLACE "^(-?)0+([0-9])" "\\1\\2" v "${v}")
    list(APPEND values ${v})
  endforeach()
  set(values_${index} ${values} PARENT_SCOPE)
endfunction()
set(index 0)
foreach(step W*5 Tab W*10 Home P)
  step_report(${index} ${step})
  math(EXPR index "${index} + 1")
endforeach()
string(REGEX MATCHALL "--keys B: [^\n]*" b_reports "${err}")
list(LENGTH b_reports b_count)
if(NOT b_count EQUAL 2)
  message(FATAL_ERROR "${b_count} reports of B, not 2: ${err}")
endif()
list(GET b_reports 0 b_on)
list(GET b_reports 1 b_off)

# 0 W*5 (orbit), 1 Tab, 2 W*10 (fly), 3 Home
if(NOT camera_0 STREQUAL "orbit" OR NOT camera_1 STREQUAL "fly" OR NOT camera_2 STREQUAL "fly")
  message(FATAL_ERROR "Tab did not switch orbit -> fly: ${camera_0}, ${camera_1}, ${camera_2}")
endif()
list(SUBLIST values_0 0 3 eye_w_orbit)
list(SUBLIST values_1 0 3 eye_start)
if(NOT eye_w_orbit STREQUAL eye_start)
  message(FATAL_ERROR "W moved the orbit camera: ${eye_start} -> ${eye_w_orbit} (1e-4 m)")
endif()
# The move along the forward vector (1e-4 units: the dot product is in 1e-8 m) and across it.
set(along 0)
set(moved2 0)
foreach(k 0 1 2)
  list(GET values_1 ${k} a)
  list(GET values_2 ${k} b)
  math(EXPR k3 "${k} + 3")
  list(GET values_1 ${k3} f)
  math(EXPR along "${along} + (${b} - ${a}) * ${f}")
  math(EXPR moved2 "${moved2} + (${b} - ${a}) * (${b} - ${a})")
endforeach()
# 3.75 m = 37500e-4 m; forward is a unit vector: along = 37500 * 1e4 = 3.75e8, to 0.5 %.
if(along LESS 373125000 OR along GREATER 376875000)
  message(FATAL_ERROR "W*10 moved the eye ${along}e-8 m along the view, not 3.75 m: ${values_1} -> ${values_2}")
endif()
# Straight ahead: |moved|^2 within 1 % of along^2 / 1e8 (nothing sideways).
math(EXPR straight "${along} / 10000 * (${along} / 10000)")
math(EXPR sideways "${moved2} - ${straight}")
if(sideways GREATER 14000000 OR sideways LESS -14000000)
  message(FATAL_ERROR "W*10 moved sideways: |move|^2 ${moved2} vs along^2 ${straight} (1e-8 m^2)")
endif()
list(SUBLIST values_3 0 3 eye_home)
if(NOT eye_home STREQUAL eye_start)
  message(FATAL_ERROR "Home did not restore the eye: ${eye_start} -> ${eye_home} (1e-4 m)")
endif()
if(NOT b_on MATCHES ", cull_front=true" OR NOT b_off MATCHES ", cull_front=false")
  message(FATAL_ERROR "B did not toggle cull_front on and off: '${b_on}', '${b_off}'")
endif()
if(NOT rest_4 MATCHES ", filter=([a-z_0-9]+)" OR CMAKE_MATCH_1 STREQUAL "")
  message(FATAL_ERROR "P did not report filter: '${rest_4}'")
endif()
execute_process(COMMAND ${LESSON} --list-params OUTPUT_VARIABLE listing)
string(REGEX MATCH "\nfilter +choice +[^ ]+ +default ([a-z_0-9]+)" _ "${listing}")
if(CMAKE_MATCH_1 STREQUAL "" OR rest_4 MATCHES ", filter=${CMAKE_MATCH_1}$")
  message(FATAL_ERROR "P left filter at its default '${CMAKE_MATCH_1}': '${rest_4}'")
endif()

# The hotkey drives the parameter itself: the same picture as setting it.
foreach(run "keys;--keys;B" "set;--set;cull_front=true")
  list(GET run 0 name)
  list(SUBLIST run 1 2 flags)
  execute_process(COMMAND ${LESSON} --headless --frames 2 --size 320x180 --strict-gl --preset acne ${flags}
                          --screenshot ${OUT_DIR}/scripted_keys_${name}.png RESULT_VARIABLE rc ERROR_VARIABLE e)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${flags}: exited ${rc}: ${e}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT_DIR}/scripted_keys_keys.png ${OUT_DIR}/scripted_keys_set.png
                RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "--keys B drew another picture than --set cull_front=true")
endif()
execute_process(COMMAND ${LESSON} --headless --frames 2 --size 320x180 --strict-gl --preset acne
                        --screenshot ${OUT_DIR}/scripted_keys_none.png)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT_DIR}/scripted_keys_keys.png ${OUT_DIR}/scripted_keys_none.png
                RESULT_VARIABLE differ)
if(NOT differ)
  message(FATAL_ERROR "cull_front changes nothing in the acne preset's picture: the comparison proves nothing")
endif()
message(STATUS "--keys ${steps}: W*10 moved ${along}e-8 m along the view; Home restored ${eye_start}; B and P drove their parameters")
