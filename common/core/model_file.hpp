#pragma once
// Model files (the lecturer's own models) into a Scene, through Assimp: Wavefront OBJ with its MTL,
// glTF 2.0 (.gltf and .glb), and whatever else the Assimp build reads. The one loading path for
// model files in the toolkit (the hand-written OBJ parser it replaces is gone).
//
// Real files are messy; each case gets a stated outcome, never a crash:
//   polygons              triangulated (Assimp's ear clipping, concave ones included)
//   missing normals       generated (smooth from the faces, creases over 60 degrees kept), noted
//   missing or unreadable textures   the material's diffuse colour is used, named in notes
//   points and lines      skipped, counted, said so in notes
//   embedded textures (.glb)         not read: the diffuse colour, said so in notes
//   open meshes (not closed 2-manifolds: boundary, non-manifold or flipped edges)   their objects'
//                         materials made two-sided (a copy where a closed mesh shares one): both
//                         faces drawn, lit and casting, as the ground truth sees them; noted
//   empty, missing, too large, corrupt, no triangles, non-finite numbers   ModelError
//
// OBJ errors name the line. Assimp 5.2.5 is the one parser that decides what loads; its OBJ
// messages name no line ("OBJ: vertex index out of range"), and it drops some bad statements
// without a word (a vertex with a non-number in it, an indented line). So, for OBJ files only,
// core/obj_locate reads the text again:
//   - when the file is refused (by Assimp, or here on what Assimp produced: a NaN or infinite
//     position, uv or normal, a face past its vertices, a polygon that crosses itself), it finds
//     the line that explains the refusal and the message becomes
//       model 'FILE': line N: reason (valid: ...)
//     (where no line explains it, as for a file with no triangles, the message names no line);
//   - when the file loads, a statement Assimp skipped or misread becomes a note naming its line.
// The scanner never refuses a file Assimp loads, nor loads one it refuses: two parsers that
// disagreed about what loads was the bug this design replaced. See core/obj_locate.hpp for what it
// checks; it runs once more over the text, after Assimp, which costs little beside Assimp's parse.
// Conventions match core/mesh.hpp: the file's axes (OBJ and glTF are both y up), uv v = 0 at the
// image's top row (Assimp's v is flipped), unit normals.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace shadowlab {

// One line: "model 'FILE': reason", or for an OBJ file "model 'FILE': line N: reason (valid: ...)".
struct ModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Files above this many bytes, or scenes above this many triangles, are refused before the GPU
// sees them (llvmpipe draws about 1M triangles a frame at class speed; 20M would take minutes).
inline constexpr std::uintmax_t kMaxModelBytes = 512ull << 20;
inline constexpr std::size_t kMaxModelTriangles = 20'000'000;

struct ModelFile {
  std::string path;
  Scene scene;                     // the file's meshes, materials and node transforms, as authored
  std::vector<std::string> notes;  // one line each: what was generated, skipped or substituted
  std::size_t skippedPoints = 0, skippedLines = 0;
  std::size_t meshesWithoutNormals = 0;
  std::size_t flatTriangles = 0;  // of no area (collinear or repeated corners): dropped
  std::size_t missingTextures = 0;
};

// Throws ModelError. Textures are resolved relative to the model's folder and decoded once to check
// them; Material::texture then holds the absolute path (gl::loadTexture accepts both).
ModelFile loadModelFile(const std::string& path);
// The same from memory (tests, the fuzz target): `hint` is the extension ("obj", "gltf", "glb");
// `name` stands for the file in messages. Textures are not looked for.
ModelFile loadModelFromMemory(const void* data, std::size_t size, const std::string& hint,
                              const std::string& name = "memory");

// The model placed for a lesson: scaled so its largest side is `size` metres (the showcase's shapes
// are 2 to 3 m, its circle of them 9 m across), centred on the origin
// in x and z, standing on y = 0, on a checker ground plane `groundSize` metres wide that receives
// shadows and casts none (as the procedural scenes' grounds): object 0, mesh 0 and material 0.
Scene placeOnGround(const ModelFile& model, float size = 4.0f, float groundSize = 30.0f);

// Where a lesson's camera looks at a placed model (placeOnGround's scene: object 0 the ground, left
// out): the centre of the model's box, from a distance at which the box's bounding sphere spans 45%
// of the view's height (vertical field of view fovY, radians), whatever the yaw and pitch. The app
// aims the camera so when --model or a dropped file makes the model the scene.
struct ModelFraming {
  glm::vec3 target{0.0f};
  float distance = 1.0f;
};
ModelFraming frameModel(const Scene& placed, float fovY);

// The process's current model: what scene=model draws in every lesson (technique/scene_cache). The
// app loads it from --model or a file dropped on the window; each load bumps the generation, so
// scene caches rebuild. A failed load throws ModelError and keeps the previous model.
const ModelFile& loadCurrentModel(const std::string& path);
const ModelFile* currentModel();  // nullptr before the first load
std::uint64_t currentModelGeneration();

}  // namespace shadowlab
