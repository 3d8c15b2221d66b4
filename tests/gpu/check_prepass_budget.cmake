# Lesson 02's depth pre-pass under the frame budget (a window under Xvfb): with depth_prepass=auto
# the frames the budget draws at half size or less skip it (their --bench rows time "view
# culling", none "depth pre-pass"), and the last frame, a full-size screenshot, has it again.
# With depth_prepass=on every frame has it, scaled or not: the control.
# Run: cmake -DXVFB_RUN=... -DLESSON=... -DOUT_DIR=... -P this
cmake_minimum_required(VERSION 3.25)
file(MAKE_DIRECTORY ${OUT_DIR})
foreach(mode auto on)
  set(csv ${OUT_DIR}/prepass_budget_${mode}.csv)
  execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x720x24" ${LESSON} --frames 8 --size 480x270 --strict-gl
                          --set budget.mode=always --set budget.fps=1000 --set depth_prepass=${mode} --bench ${csv}
                          --screenshot ${OUT_DIR}/prepass_budget_${mode}.png
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "depth_prepass=${mode}: the windowed run exited ${rc}: ${err}")
  endif()
  file(STRINGS ${csv} rows)
  list(REMOVE_AT rows 0)
  set(half_frames "")    # frames drawn at scale <= 0.5
  set(with_prepass "")   # frames with a "depth pre-pass" row
  set(culling_only "")   # frames with a "view culling" row
  foreach(row IN LISTS rows)
    string(REPLACE "," ";" f "${row}")
    list(GET f 0 frame)
    list(GET f 1 pass)
    list(GET f 6 scale)
    if(scale LESS_EQUAL 0.5)
      list(APPEND half_frames ${frame})
    endif()
    if(pass STREQUAL "depth pre-pass")
      list(APPEND with_prepass ${frame})
    elseif(pass STREQUAL "view culling")
      list(APPEND culling_only ${frame})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES half_frames)
  if(NOT half_frames)
    message(FATAL_ERROR "depth_prepass=${mode}: no frame at half size or less with a 1 ms budget:\n${rows}")
  endif()
  if(NOT 7 IN_LIST with_prepass)
    message(FATAL_ERROR "depth_prepass=${mode}: the full-size screenshot frame had no depth pre-pass:\n${rows}")
  endif()
  foreach(frame IN LISTS half_frames)
    if(mode STREQUAL "auto" AND (frame IN_LIST with_prepass OR NOT frame IN_LIST culling_only))
      message(FATAL_ERROR "depth_prepass=auto: frame ${frame}, drawn at half size or less, had its pre-pass:\n${rows}")
    endif()
    if(mode STREQUAL "on" AND NOT frame IN_LIST with_prepass)
      message(FATAL_ERROR "depth_prepass=on: frame ${frame} had no pre-pass:\n${rows}")
    endif()
  endforeach()
  message(STATUS "depth_prepass=${mode}: frames at half size or less: ${half_frames}; with the pre-pass: ${with_prepass}")
endforeach()
