// gen_textures OUTDIR: writes every procedural course texture as PNG into OUTDIR (textures/ in
// the repository holds the committed copies; test_textures proves they are reproducible).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "core/image.hpp"
#include "core/texture_gen.hpp"

int main(int argc, char** argv) {
  if (argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::printf("usage: gen_textures OUTDIR (writes the course's procedural textures there as PNG)\n");
    return 0;
  }
  // A flag is a mistake, not a directory to create.
  if (argc != 2 || argv[1][0] == '-' || argv[1][0] == '\0') {
    std::fprintf(stderr, "gen_textures: %s; usage: gen_textures OUTDIR\n",
                 argc != 2 ? "one argument, the output directory"
                           : (std::string("unexpected argument '") + argv[1] + "'").c_str());
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    for (const auto& [name, image] : shadowlab::generateCourseTextures()) {
      const std::string path = (dir / name).string();
      shadowlab::savePng(path, image);
      std::printf("%s %dx%dx%d\n", path.c_str(), image.width, image.height, image.channels);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gen_textures: %s\n", e.what());
    return 1;
  }
  return 0;
}
