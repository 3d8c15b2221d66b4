# Command-line tools built with the full (GL) configuration.
#   gen_textures OUTDIR   writes the procedural course textures (textures/ holds committed copies)
add_executable(gen_textures ${CMAKE_SOURCE_DIR}/tools/gen_textures.cpp)
target_link_libraries(gen_textures PRIVATE shadowlab_core)
