# Command-line tools built with the full (GL) configuration.
#   gen_textures OUTDIR   writes the procedural course textures (textures/ holds committed copies)
add_executable(gen_textures ${CMAKE_SOURCE_DIR}/tools/gen_textures.cpp)
target_link_libraries(gen_textures PRIVATE shadowlab_core)

# grade_report OUT RESULTS...: one grade (score.json, junit.xml, Gradescope results.json) from
# the results files the graders write (make grade, make grade-submission).
add_executable(grade_report ${CMAKE_SOURCE_DIR}/tools/grading/grade_report.cpp)
target_link_libraries(grade_report PRIVATE shadowlab_grading)

# grade_isolated --reference=REF --results-json=FILE -- GRADER: the grader run one exercise at a
# time, each in its own process with a time and a memory limit (make grade, make grade-submission).
add_executable(grade_isolated ${CMAKE_SOURCE_DIR}/tools/grading/grade_isolated.cpp)
target_link_libraries(grade_isolated PRIVATE shadowlab_grading)
