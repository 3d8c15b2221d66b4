# gpu.NN.withheld: the student handout's lesson, as the handout has it, without the reference GLSL
# of any exercise (the `withheld` lines of tools/handout/sealed_shaders.txt). On a copy of the
# shader tree without those files (SHADOWLAB_ROOT):
#   - the lesson runs (strict GL) and, in a view that calls a withheld function (-DVIEW=name=value,
#     the exercise's usedWhen; empty: every view calls one), its banner says the student's
#     exercises.glsl draws instead; with VIEW given, the default view (which calls none) has no banner;
#   - the driver receives no line of the withheld files (Mesa writes every shader it is given to
#     MESA_SHADER_DUMP_PATH): the reference GLSL is in no form a student could recover there.
# The same run in this tree, where the files are, must hand the driver a reference line: the check
# can fail. -DLESSON_BINARY -DLESSON (folder name) -DSOURCE (this tree) -DOUT (scratch folder).
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT}/dump_tree ${OUT}/dump_handout)
file(COPY ${SOURCE}/shaders DESTINATION ${OUT}/root)
foreach(dir lessons textures)
  file(CREATE_LINK ${SOURCE}/${dir} ${OUT}/root/${dir} SYMBOLIC)
endforeach()

# GLSL's ; [ ] would split or join CMake list items: every text is compared with them spelled out.
macro(spell var)
  string(REPLACE ";" "@S@" ${var} "${${var}}")
  string(REPLACE "[" "@L@" ${var} "${${var}}")
  string(REPLACE "]" "@R@" ${var} "${${var}}")
endmacro()

# The withheld files and their answer lines: code (not comments), long enough to be an answer,
# and in no shader the handout keeps (the signatures are in the student's exercises.glsl too, some
# plumbing in the shaders that include them).
file(STRINGS ${SOURCE}/tools/handout/sealed_shaders.txt manifest REGEX "^withheld ")
set(withheld "")
foreach(line IN LISTS manifest)
  string(REGEX REPLACE "^withheld[ \t]+([^ \t#]+).*" "\\1" path "${line}")
  file(REMOVE ${OUT}/root/shaders/${path})
  list(APPEND withheld ${path})
endforeach()
file(GLOB_RECURSE kept ${OUT}/root/shaders/*)
set(rest "")
foreach(f IN LISTS kept)
  file(READ ${f} t)
  spell(t)
  string(APPEND rest "${t}")
endforeach()
set(answers "")
foreach(path IN LISTS withheld)
  file(READ ${SOURCE}/shaders/${path} code)
  spell(code)
  string(REPLACE "\n" ";" code "${code}")
  foreach(c IN LISTS code)
    string(STRIP "${c}" c)
    string(LENGTH "${c}" n)
    string(FIND "${rest}" "${c}" kept_too)
    if(n GREATER_EQUAL 30 AND kept_too EQUAL -1 AND NOT c MATCHES "^//" AND NOT c MATCHES "^\\*")
      list(APPEND answers "${c}")
    endif()
  endforeach()
endforeach()
list(LENGTH answers answer_count)
if(answer_count LESS 20)
  message(FATAL_ERROR "only ${answer_count} answer lines in the withheld files: is the manifest read right?")
endif()

# Every line of every shader the driver was given, from one run.
function(run_lesson root dump result_var)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env SHADOWLAB_ROOT=${root} MESA_SHADER_DUMP_PATH=${dump}
                          SHADOWLAB_STRICT_GL=1 ${LESSON_BINARY} --headless --frames 2 --size 320x180
                          --set impl=reference ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${LESSON} (SHADOWLAB_ROOT=${root}) exited ${rc}:\n${out}${err}")
  endif()
  file(GLOB dumped ${dump}/*)
  list(LENGTH dumped n)
  if(n EQUAL 0)
    message(FATAL_ERROR "Mesa dumped no shader into ${dump}: MESA_SHADER_DUMP_PATH unsupported? (the check needs it)")
  endif()
  set(text "")
  foreach(f IN LISTS dumped)
    file(READ ${f} t)
    spell(t)
    string(APPEND text "${t}")
  endforeach()
  set(${result_var} "${out}" PARENT_SCOPE)
  set(${result_var}_shaders "${text}" PARENT_SCOPE)
endfunction()

function(answer_lines_in text result_var)
  set(found "")
  foreach(a IN LISTS answers)
    string(FIND "${text}" "${a}" at)
    if(at GREATER -1)
      list(APPEND found "${a}")
    endif()
  endforeach()
  set(${result_var} "${found}" PARENT_SCOPE)
endfunction()

run_lesson(${SOURCE} ${OUT}/dump_tree tree)
answer_lines_in("${tree_shaders}" in_tree)
if(NOT in_tree)
  message(FATAL_ERROR "in this tree the driver got no line of the withheld files: the check below could not fail")
endif()

set(view_args "")
if(VIEW)
  set(view_args --set ${VIEW})
endif()
run_lesson(${OUT}/root ${OUT}/dump_handout handout ${view_args})
if(NOT handout MATCHES "your GLSL draws where the reference's is withheld" OR NOT handout MATCHES "shaders/${LESSON}/exercises.glsl")
  message(FATAL_ERROR "without the reference GLSL the banner does not say whose GLSL draws:\n${handout}")
endif()
if(VIEW)
  file(MAKE_DIRECTORY ${OUT}/dump_default)
  run_lesson(${OUT}/root ${OUT}/dump_default default_view --show-ui)  # the UI runs the exercises' cases too
  if(default_view MATCHES "your GLSL draws where the reference's is withheld")
    message(FATAL_ERROR "the default view calls no withheld function (it takes ${VIEW}), yet the banner says "
                        "the student's GLSL draws:\n${default_view}")
  endif()
endif()
answer_lines_in("${handout_shaders}" leaked)
if(leaked)
  message(FATAL_ERROR "without the withheld files the driver still got reference lines:\n${leaked}")
endif()
list(LENGTH in_tree k)
message(STATUS "${LESSON}: without the withheld files it runs, says so, and gives the driver none of the "
               "${answer_count} answer lines (in this tree it gave ${k})")
