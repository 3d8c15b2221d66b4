// OBJ text through the model loader (core/model_file: Assimp from memory with the "obj" hint, and
// core/obj_locate naming the line of a refusal): a scene whose indices, normals and uvs are
// consistent and finite, or a one-line ModelError naming the file. The corpus (seeds and
// regressions) began as the former hand-written parser's.
#include <sanitizer/asan_interface.h>

#include <cmath>
#include <cstdlib>
#include <new>

#include "core/model_file.hpp"
#include "fuzz_support.hpp"

using namespace shadowlab;

// Speed. Assimp 5.2.5's OBJ importer reads every file through an IOStreamBuffer whose cache is
// 16 MiB (4096 * 4096 bytes, fixed in the library), allocated and filled twice per file. Under
// ASan a block that large is a fresh mmap each time: the page faults and fills made this target
// about 25 executions a second (perf: exc_page_fault 25 %, memset 18 %, the kernel's page
// handling most of the rest), where an Importer made per file costs microseconds (so the loader
// is fuzzed as the lessons call it, a new Importer each time, Assimp's logging off). So this target
// replaces plain operator new and delete (the other forms stay ASan's) to keep one block of that
// size: handed out whole, poisoned while returned (ASan reports any use of it then, as it would
// a freed block), never unmapped. Everything else goes to malloc and free, which ASan checks.
namespace {
constexpr std::size_t kObjCacheBytes = std::size_t(4096) * 4096;
void* cacheBlock = nullptr;
bool cacheInUse = false;

void* allocate(std::size_t size) noexcept {
  if (size == kObjCacheBytes && !cacheInUse) {
    if (!cacheBlock) cacheBlock = std::malloc(size);
    if (cacheBlock) {
      cacheInUse = true;
      ASAN_UNPOISON_MEMORY_REGION(cacheBlock, size);
      return cacheBlock;
    }
  }
  return std::malloc(size ? size : 1);
}

void release(void* p) noexcept {
  if (p && p == cacheBlock) {
    cacheInUse = false;
    ASAN_POISON_MEMORY_REGION(cacheBlock, kObjCacheBytes);
    return;
  }
  std::free(p);
}
}  // namespace

void* operator new(std::size_t size) {
  if (void* p = allocate(size)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void operator delete(void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const ModelFile model = loadModelFromMemory(data, size, "obj", "fuzz.obj");
    FUZZ_CHECK(!model.scene.objects.empty());
    for (const SceneObject& o : model.scene.objects)
      FUZZ_CHECK(o.mesh < model.scene.meshes.size() && o.material < model.scene.materials.size());
    for (const Mesh& m : model.scene.meshes) {
      FUZZ_CHECK(!m.indices.empty() && m.indices.size() % 3 == 0);
      FUZZ_CHECK(m.normals.size() == m.positions.size() && m.uvs.size() == m.positions.size());
      for (std::uint32_t i : m.indices) FUZZ_CHECK(i < m.positions.size());
      for (std::size_t i = 0; i < m.positions.size(); ++i) {
        FUZZ_CHECK(std::isfinite(m.positions[i].x) && std::isfinite(m.positions[i].y) &&
                   std::isfinite(m.positions[i].z));
        FUZZ_CHECK(std::abs(glm::length(m.normals[i]) - 1.0f) < 1e-3f);
        FUZZ_CHECK(std::isfinite(m.uvs[i].x) && std::isfinite(m.uvs[i].y));
      }
    }
    for (const std::string& note : model.notes) FUZZ_CHECK(!note.empty() && note.find('\n') == std::string::npos);
  } catch (const ModelError& e) {
    // One line naming the file: "model 'fuzz.obj': reason" or "model 'fuzz.obj': line N: reason".
    const std::string message = e.what();
    FUZZ_CHECK(message.rfind("model 'fuzz.obj': ", 0) == 0 && message.find('\n') == std::string::npos);
  }
  return 0;
}
