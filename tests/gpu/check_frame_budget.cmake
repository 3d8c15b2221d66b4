# The frame budget in a real window (Xvfb): asked for 1000 fps it must lower the render scale in the
# frames after the warm-up, and the last frame, a screenshot, must be drawn at the full size
# (scale 1 in the --bench CSV, and a PNG of the window's size). Headless the scale stays 1.
# Run: cmake -DXVFB_RUN=... -DLESSON=... -DOUT_DIR=... -P this
file(MAKE_DIRECTORY ${OUT_DIR})
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x720x24" ${LESSON} --frames 8 --size 480x270 --strict-gl
                        --set budget.mode=always --set budget.fps=1000 --bench ${OUT_DIR}/budget_window.csv
                        --screenshot ${OUT_DIR}/budget_window.png
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "windowed run exited ${rc}: ${err}")
endif()
file(STRINGS ${OUT_DIR}/budget_window.csv rows)
list(REMOVE_AT rows 0)
set(scaled 0)
set(last_scale "")
foreach(row IN LISTS rows)
  string(REPLACE "," ";" f "${row}")
  list(GET f 0 frame)
  list(GET f 6 scale)
  if(frame EQUAL 7)
    set(last_scale ${scale})
  elseif(scale LESS 1)
    set(scaled 1)
  endif()
endforeach()
if(NOT scaled)
  message(FATAL_ERROR "no frame was drawn at a reduced scale with a 1 ms budget:\n${rows}")
endif()
if(NOT last_scale EQUAL 1)
  message(FATAL_ERROR "the screenshot frame was drawn at scale '${last_scale}', not at full size")
endif()
file(READ ${OUT_DIR}/budget_window.png head LIMIT 24 HEX)
string(SUBSTRING "${head}" 32 16 size)  # IHDR width and height, big-endian
if(NOT size STREQUAL "000001e00000010e")
  message(FATAL_ERROR "the screenshot is not 480x270 (IHDR ${size})")
endif()
execute_process(COMMAND ${LESSON} --headless --frames 6 --size 320x180 --set budget.mode=always --set budget.fps=1000
                        --bench ${OUT_DIR}/budget_headless.csv RESULT_VARIABLE rc)
file(STRINGS ${OUT_DIR}/budget_headless.csv hrows REGEX ",[0-9.]+$")
foreach(row IN LISTS hrows)
  if(NOT row MATCHES ",1$")
    message(FATAL_ERROR "a headless frame was scaled: ${row}")
  endif()
endforeach()
message(STATUS "window: scaled frames, then a full-size screenshot; headless: always full size")
