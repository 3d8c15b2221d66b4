#include "core/model_file.hpp"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <cctype>
#include <glm/gtc/matrix_transform.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <system_error>

#include "core/image.hpp"
#include "core/mesh_gen.hpp"
#include "core/obj_locate.hpp"
#include "core/polygon.hpp"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

// A refusal, and what it refused: for an OBJ file, locateObjFault then names the line at fault.
struct Refusal : ModelError {
  ObjFault fault;
  Refusal(const std::string& message, ObjFault f) : ModelError(message), fault(f) {}
};

// A refusal no line of the file explains (its size, its emptiness, a scene with no triangles).
[[noreturn]] void fail(const std::string& name, const std::string& reason) {
  throw ModelError("model '" + name + "': " + reason);
}

// A refusal of what the file says, at a line where it is an OBJ file.
[[noreturn]] void refuse(const std::string& name, ObjFault fault, const std::string& reason) {
  throw Refusal("model '" + name + "': " + reason, fault);
}

bool isObj(const std::string& extension) {
  std::string e = extension;
  for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e == "obj" || e == ".obj";
}

// Runs `load` (Assimp decides whether the file loads). An OBJ file's refusal gets the line at fault,
// "model 'FILE': line N: reason (valid: ...)", where the text has one that explains it. An OBJ file
// Assimp loads is scanned too, never to refuse it: a line Assimp 5.2.5 skipped or misread without a
// word (a vertex with a non-number, an indented statement) becomes a note, so nothing is silent.
// Assimp's warnings during one import, for the notes: it drops what it cannot use (a face with an
// index past its mesh's vertices) with a warning only, which the lesson would otherwise never say.
class ImportWarnings {
 public:
  ImportWarnings() {
    Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(new Stream(lines_), Assimp::Logger::Warn | Assimp::Logger::Err);
  }
  ~ImportWarnings() { Assimp::DefaultLogger::kill(); }
  ImportWarnings(const ImportWarnings&) = delete;
  ImportWarnings& operator=(const ImportWarnings&) = delete;
  void into(ModelFile& model) const {
    for (const std::string& line : lines_) model.notes.push_back("the importer (Assimp) warned: " + line);
  }

 private:
  struct Stream : Assimp::LogStream {  // the logger owns and deletes it
    explicit Stream(std::vector<std::string>& lines) : lines(lines) {}
    void write(const char* message) override {
      std::string m = message;  // "Warn,  T0: Some faces had out-of-range indices. ...\n"
      if (const auto colon = m.find(": "); colon != std::string::npos) m.erase(0, colon + 2);
      while (!m.empty() && std::isspace(static_cast<unsigned char>(m.back()))) m.pop_back();
      if (!m.empty() && std::find(lines.begin(), lines.end(), m) == lines.end()) lines.push_back(m);
    }
    std::vector<std::string>& lines;
  };
  std::vector<std::string> lines_;
};

ModelFile withLine(const std::string& name, bool obj, const std::function<std::string()>& text,
                   const std::function<ModelFile()>& load) {
  try {
    const ImportWarnings warnings;
    ModelFile model = load();
    warnings.into(model);
    if (obj)
      if (const std::optional<ObjLine> at = locateObjFault(text(), ObjFault::any))
        model.notes.insert(
            model.notes.begin(),  // first: the status line shows the first note
            "line " + std::to_string(at->line) + ": " + at->reason +
                ". Assimp 5.2.5 loaded the file, skipping or misreading this statement: check the model");
    return model;
  } catch (const Refusal& e) {
    if (!obj) throw ModelError(e.what());
    const std::optional<ObjLine> at = locateObjFault(text(), e.fault);
    if (!at) throw ModelError(e.what());
    throw ModelError("model '" + name + "': line " + std::to_string(at->line) + ": " + at->reason);
  }
}

// Assimp's messages sometimes span lines; ours are one.
std::string oneLine(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\r', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s.empty() ? std::string("Assimp could not read it") : s;
}

// Degenerate faces and primitive types sorted out (points and lines end up in meshes of their own,
// which we count and skip), uv v flipped to the toolkit's top-row origin, the structure validated.
// Polygons are triangulated here (core/polygon), not by aiProcess_Triangulate, which in Assimp 5.2.5
// covered a concave pentagon's notch. Normals and welding come after (sortPrimitives), so we can say which
// meshes had no normals; Assimp generates them only on unwelded ("verbose") vertices.
constexpr unsigned kImportSteps =
    aiProcess_SortByPType | aiProcess_FlipUVs | aiProcess_ValidateDataStructure | aiProcess_FindDegenerates;

// Generated normals smooth across edges up to this angle; sharper ones (a box's corners) stay creased.
constexpr float kCreaseDegrees = 60.0f;

glm::mat4 toGlm(const aiMatrix4x4& m) {
  // Assimp's matrices are row-major with translation in the last column; glm is column-major.
  glm::mat4 out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[c][r] = m[r][c];
  return out;
}

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A unit normal; a degenerate or non-finite one (a face of no area) becomes +y.
glm::vec3 unitNormal(const aiVector3D& n) {
  const glm::vec3 v(n.x, n.y, n.z);
  const float length = glm::length(v);
  if (!std::isfinite(length) || length < 1e-12f) return glm::vec3(0, 1, 0);
  return v / length;
}

// A triangle of no area (its corners in a line, or two of them one point) draws nothing and casts
// nothing: relative to its longest edge, |cross| below 1e-6 of that edge squared.
bool noArea(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 e1 = b - a, e2 = c - a, e3 = c - b;
  const float longest = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)});
  return glm::length(glm::cross(e1, e2)) <= 1e-6f * longest;
}

// The mesh's triangles; those of no area are dropped and counted in `flat`.
Mesh convertMesh(const aiMesh& in, const std::string& name, std::size_t& flat) {
  Mesh m;
  m.positions.reserve(in.mNumVertices);
  for (unsigned i = 0; i < in.mNumVertices; ++i) {
    if (!finite(in.mVertices[i]))
      refuse(name, ObjFault::nonFinitePosition, "mesh '" + std::string(in.mName.C_Str()) + "' has a non-finite vertex");
    m.positions.emplace_back(in.mVertices[i].x, in.mVertices[i].y, in.mVertices[i].z);
    m.normals.push_back(in.mNormals ? unitNormal(in.mNormals[i]) : glm::vec3(0, 1, 0));
    const aiVector3D uv = in.mTextureCoords[0] ? in.mTextureCoords[0][i] : aiVector3D(0, 0, 0);
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
      refuse(name, ObjFault::nonFiniteUv, "mesh '" + std::string(in.mName.C_Str()) + "' has a non-finite uv");
    m.uvs.emplace_back(uv.x, uv.y);
  }
  m.indices.reserve(std::size_t(in.mNumFaces) * 3);
  std::vector<glm::vec3> corners;
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (face.mNumIndices < 3) continue;  // SortByPType put points and lines elsewhere; be sure
    corners.clear();
    for (unsigned k = 0; k < face.mNumIndices; ++k) {
      if (face.mIndices[k] >= in.mNumVertices)
        refuse(name, ObjFault::vertexIndex, "a face indexes past its mesh's vertices");
      corners.push_back(m.positions[face.mIndices[k]]);
    }
    try {
      for (const auto& t : triangulatePolygon(corners)) {
        if (noArea(corners[t[0]], corners[t[1]], corners[t[2]])) {
          ++flat;
          continue;
        }
        for (std::uint32_t k : t) m.indices.push_back(face.mIndices[k]);
      }
    } catch (const std::invalid_argument& e) {
      refuse(name, ObjFault::selfCrossing, "mesh '" + std::string(in.mName.C_Str()) + "': " + e.what());
    }
  }
  return m;
}

std::string colourText(const glm::vec3& c) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "(%.2f, %.2f, %.2f)", c.x, c.y, c.z);
  return buffer;
}

// The diffuse texture of `in`, resolved against `folder` and decoded once; "" with a note when it
// is missing, unreadable or embedded (the diffuse colour stands in).
std::string resolveTexture(const aiMaterial& in, const Material& m, const fs::path& folder, ModelFile& out) {
  aiString file;
  if (in.GetTextureCount(aiTextureType_DIFFUSE) == 0 || in.GetTexture(aiTextureType_DIFFUSE, 0, &file) != AI_SUCCESS)
    return {};
  const std::string name = file.C_Str();
  auto missing = [&](const std::string& what) {
    ++out.missingTextures;
    out.notes.push_back(what + "; material '" + m.name + "' uses its diffuse colour " + colourText(m.albedo));
    return std::string();
  };
  if (name.empty()) return {};
  if (name[0] == '*') return missing("texture " + name + " is embedded in the file, which this loader does not read");
  if (folder.empty()) return missing("texture '" + name + "' not looked for (model read from memory)");
  std::string relative = name;
  std::replace(relative.begin(), relative.end(), '\\', '/');  // OBJ files written on Windows
  const fs::path resolved =
      (fs::path(relative).is_absolute() ? fs::path(relative) : folder / relative).lexically_normal();
  std::error_code ec;
  if (!fs::is_regular_file(resolved, ec)) return missing("texture '" + resolved.string() + "' not found");
  try {
    loadImage(resolved.string(), 4);
  } catch (const std::exception& e) {
    return missing("texture '" + resolved.string() + "' unreadable (" + e.what() + ")");
  }
  return fs::absolute(resolved).lexically_normal().string();
}

Material convertMaterial(const aiMaterial& in, std::size_t index, const fs::path& folder, ModelFile& out) {
  Material m;
  aiString name;
  m.name = in.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0 ? name.C_Str()
                                                                         : "material " + std::to_string(index);
  aiColor4D colour;
  if (in.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS || in.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
    m.albedo = glm::clamp(glm::vec3(colour.r, colour.g, colour.b), glm::vec3(0.0f), glm::vec3(1.0f));
  if (!std::isfinite(m.albedo.x + m.albedo.y + m.albedo.z)) m.albedo = glm::vec3(0.8f);
  float shininess = 0;
  if (in.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && std::isfinite(shininess) && shininess >= 1.0f)
    m.shininess = std::min(shininess, 1024.0f);
  int twoSided = 0;
  if (in.Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS) m.twoSided = twoSided != 0;
  m.texture = resolveTexture(in, m, folder, out);
  return m;
}

void addNode(const aiNode& node, const glm::mat4& parent, const std::vector<int>& meshIndex, const aiScene& in,
             Scene& scene, int depth) {
  if (depth > 256) return;  // a cycle or an absurd hierarchy: Assimp validates, this is a backstop
  const glm::mat4 model = parent * toGlm(node.mTransformation);
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const unsigned i = node.mMeshes[k];
    if (i >= meshIndex.size() || meshIndex[i] < 0) continue;  // a point or line mesh: skipped
    SceneObject o;
    o.name = node.mName.length > 0 ? node.mName.C_Str() : "mesh " + std::to_string(i);
    o.mesh = std::uint32_t(meshIndex[i]);
    o.material = std::min<std::uint32_t>(in.mMeshes[i]->mMaterialIndex, std::uint32_t(scene.materials.size() - 1));
    o.model = model;
    scene.addObject(std::move(o));
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    if (node.mChildren[c]) addNode(*node.mChildren[c], model, meshIndex, in, scene, depth + 1);
}

// Counts the point and line meshes, says which meshes need normals, and generates those.
void sortPrimitives(Assimp::Importer& importer, const aiScene*& in, ModelFile& out) {
  for (unsigned i = 0; i < in->mNumMeshes; ++i) {
    const aiMesh& mesh = *in->mMeshes[i];
    if (mesh.mPrimitiveTypes & aiPrimitiveType_POINT) out.skippedPoints += mesh.mNumFaces;
    else if (mesh.mPrimitiveTypes & aiPrimitiveType_LINE) out.skippedLines += mesh.mNumFaces;
    else if (!mesh.HasNormals()) ++out.meshesWithoutNormals;
    else
      for (unsigned v = 0; v < mesh.mNumVertices; ++v)
        if (!finite(mesh.mNormals[v]))
          refuse(out.path, ObjFault::nonFiniteNormal,
                 "mesh '" + std::string(mesh.mName.C_Str()) + "' has a non-finite normal");
  }
  if (out.skippedPoints || out.skippedLines)
    out.notes.push_back("skipped " + std::to_string(out.skippedPoints) + " points and " +
                        std::to_string(out.skippedLines) + " lines (only triangles cast and receive shadows)");
  if (out.meshesWithoutNormals)
    out.notes.push_back(std::to_string(out.meshesWithoutNormals) + " meshes had no normals: generated smooth ones " +
                        "from the faces (creases over " + std::to_string(int(kCreaseDegrees)) + " degrees kept)");
  importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, kCreaseDegrees);
  in = importer.ApplyPostProcessing(aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices);
  if (!in) refuse(out.path, ObjFault::any, "generating normals failed: " + oneLine(importer.GetErrorString()));
}

// Real models are rarely closed 2-manifolds (a chimney without a lid, a one-sided leaf, flipped
// faces). Back-face culled, such a surface vanishes wherever the camera or the light looks at its
// inner side, while the ground truth (Embree culls nothing) still hits it, so the measured error of
// a loaded model counted walls that were simply not drawn. Every object whose mesh is open
// (core/mesh's analyseTopology, as lesson 04 counts open edges) gets a two-sided material: the lit
// pass flips the normal toward the eye and neither it nor the casters cull (gl/scene_draw,
// technique/casters). A material a closed mesh shares is copied first, so closed meshes keep their
// culling. Returns how many meshes were open.
std::size_t drawOpenMeshesTwoSided(Scene& scene) {
  std::vector<char> open(scene.meshes.size());
  std::size_t count = 0;
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    open[i] = !analyseTopology(scene.meshes[i]).closed();
    count += open[i] ? 1 : 0;
  }
  std::vector<int> twoSidedCopy(scene.materials.size(), -1);  // material -> its two-sided version
  for (SceneObject& o : scene.objects) {
    if (!open[o.mesh] || scene.materials[o.material].twoSided) continue;
    if (twoSidedCopy[o.material] < 0) {
      const bool sharedWithClosed = std::any_of(scene.objects.begin(), scene.objects.end(), [&](const SceneObject& c) {
        return c.material == o.material && !open[c.mesh];
      });
      Material m = scene.materials[o.material];
      m.twoSided = true;
      if (sharedWithClosed) {
        m.name += " (two-sided)";
        twoSidedCopy[o.material] = int(scene.addMaterial(std::move(m)));
      } else {
        scene.materials[o.material] = std::move(m);
        twoSidedCopy[o.material] = int(o.material);
      }
    }
    o.material = std::uint32_t(twoSidedCopy[o.material]);
  }
  return count;
}

ModelFile convertScene(Assimp::Importer& importer, const aiScene* in, const std::string& name, const fs::path& folder) {
  ModelFile out;
  out.path = name;
  if (!in) refuse(name, ObjFault::any, "not a readable model file: " + oneLine(importer.GetErrorString()));
  if ((in->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !in->mRootNode)
    refuse(name, ObjFault::any, "the file holds no complete scene");
  sortPrimitives(importer, in, out);
  for (unsigned i = 0; i < in->mNumMaterials; ++i)
    out.scene.addMaterial(convertMaterial(*in->mMaterials[i], i, folder, out));
  if (out.scene.materials.empty()) out.scene.addMaterial(Material{"default"});
  std::vector<int> meshIndex(in->mNumMeshes, -1);
  std::size_t triangles = 0;
  for (unsigned i = 0; i < in->mNumMeshes; ++i) {
    const aiMesh& mesh = *in->mMeshes[i];
    if (!(mesh.mPrimitiveTypes & (aiPrimitiveType_TRIANGLE | aiPrimitiveType_POLYGON))) continue;
    triangles += mesh.mNumFaces;
    if (triangles > kMaxModelTriangles)
      fail(name, "more than " + std::to_string(kMaxModelTriangles) + " triangles: too large to draw at class speed");
    Mesh converted = convertMesh(mesh, name, out.flatTriangles);
    if (converted.indices.empty()) continue;
    meshIndex[i] = int(out.scene.addMesh(std::move(converted)));
  }
  addNode(*in->mRootNode, glm::mat4(1.0f), meshIndex, *in, out.scene, 0);
  const std::string flat = std::to_string(out.flatTriangles) + " triangles of no area (corners in a line or repeated)";
  if (out.scene.objects.empty() || out.scene.bounds().empty())
    fail(name, "no triangles to draw (" + (out.flatTriangles > 0 ? flat + ", " : std::string()) +
                   std::to_string(out.skippedPoints) + " points and " + std::to_string(out.skippedLines) +
                   " lines skipped)");
  if (out.flatTriangles > 0) out.notes.push_back("dropped " + flat + ": they draw nothing");
  const Aabb box = out.scene.bounds();
  if (!std::isfinite(glm::length(box.extent())))
    fail(name, "its size overflows a float (coordinates or node transforms too large)");
  if (const std::size_t open = drawOpenMeshesTwoSided(out.scene))
    out.notes.push_back(std::to_string(open) + " of " + std::to_string(out.scene.meshes.size()) +
                        " meshes are open (not closed 2-manifolds): drawn two-sided, both faces lit and "
                        "casting, none culled");
  out.scene.name = fs::path(name).filename().string();
  return out;
}

}  // namespace

ModelFile loadModelFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) fail(path, "no such file");
  if (!fs::is_regular_file(status)) fail(path, "not a regular file");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec) fail(path, "cannot read its size: " + ec.message());
  if (bytes == 0) fail(path, "the file is empty");
  if (bytes > kMaxModelBytes)
    fail(path, std::to_string(bytes >> 20) + " MiB is over the " + std::to_string(kMaxModelBytes >> 20) + " MiB limit");
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  const auto text = [&] {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream all;
    all << file.rdbuf();
    return all.str();
  };
  return withLine(path, isObj(fs::path(path).extension().string()), text, [&] {
    Assimp::Importer importer;
    return convertScene(importer, importer.ReadFile(path, kImportSteps), path, folder);
  });
}

ModelFile loadModelFromMemory(const void* data, std::size_t size, const std::string& hint, const std::string& name) {
  if (size == 0) fail(name, "the file is empty");
  if (size > kMaxModelBytes) fail(name, "over the " + std::to_string(kMaxModelBytes >> 20) + " MiB limit");
  const auto text = [&] { return std::string(static_cast<const char*>(data), size); };
  return withLine(name, isObj(hint), text, [&] {
    Assimp::Importer importer;
    return convertScene(importer, importer.ReadFileFromMemory(data, size, kImportSteps, hint.c_str()), name,
                        fs::path());
  });
}

}  // namespace shadowlab
