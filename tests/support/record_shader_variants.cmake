# Records the shader variants one lesson asks for (tests/shaders.cmake, shader.variants.record.*):
# runs LESSON over its default view and every preset (--list-presets), then each of EXTRA (runs
# that reach a variant no preset does: '|' between runs, spaces between a run's arguments), then
# STUDENT (the lesson's GLSL-exercise build, if any) with impl=student, each for one small frame
# with SHADOWLAB_SHADER_VARIANTS=LOG, which starts empty. Any run that fails fails the recording:
# a variant it never reached would otherwise pass unnoticed.
cmake_minimum_required(VERSION 3.22)
file(REMOVE ${LOG})
get_filename_component(dir ${LOG} DIRECTORY)
file(MAKE_DIRECTORY ${dir})
set(ENV{SHADOWLAB_SHADER_VARIANTS} ${LOG})
unset(ENV{SHADOWLAB_SPECIALISE})    # =0 would record only the generic programs
unset(ENV{SHADOWLAB_FLOOR_SHADER})  # =1 would swap every fragment stage for the floor's
set(frame --headless --frames 1 --size 160x90)

function(record binary)
  execute_process(COMMAND ${binary} ${frame} ${ARGN} RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${binary} ${ARGN} exited ${rc}:\n${err}")
  endif()
endfunction()

string(TIMESTAMP start "%s")
execute_process(COMMAND ${LESSON} --list-presets RESULT_VARIABLE rc OUTPUT_VARIABLE presets ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${LESSON} --list-presets exited ${rc}:\n${err}")
endif()
string(REGEX REPLACE "[ \t\r\n]+" ";" presets "${presets}")
list(REMOVE_ITEM presets "")
set(runs 0)
foreach(preset IN LISTS presets)
  record(${LESSON} --preset ${preset})
  math(EXPR runs "${runs} + 1")
endforeach()
string(REPLACE "|" ";" extra_runs "${EXTRA}")
foreach(run IN LISTS extra_runs)
  separate_arguments(args UNIX_COMMAND "${run}")
  record(${LESSON} ${args})
  math(EXPR runs "${runs} + 1")
endforeach()
if(STUDENT)
  record(${STUDENT} --set impl=student)
  math(EXPR runs "${runs} + 1")
endif()
if(NOT EXISTS ${LOG})
  message(FATAL_ERROR "${runs} runs recorded no program into ${LOG}: is the SHADOWLAB_SHADER_VARIANTS hook gone?")
endif()
file(STRINGS ${LOG} lines)
list(LENGTH lines count)
string(TIMESTAMP stop "%s")
math(EXPR seconds "${stop} - ${start}")
message(STATUS "${runs} runs recorded ${count} programs into ${LOG} in ${seconds} s")
