// The browser build's ground truth: none. Embree traces on the CPU natively; a page cannot run it,
// so every GroundTruth says so (the measurement shows the line on screen, --measure exits with it).
#include <stdexcept>

#include "measure/ground_truth.hpp"

namespace shadowlab::measure {

struct GroundTruth::Impl {};

namespace {
[[noreturn]] void native() { throw std::runtime_error("ground truth: run the lesson natively (make run)"); }
}  // namespace

GroundTruth::GroundTruth(const Scene&, TextureLookup, GroundTruthOptions) { native(); }
GroundTruth::GroundTruth(const Scene&, const std::map<std::string, Image8>&, GroundTruthOptions) { native(); }
GroundTruth::~GroundTruth() = default;
void GroundTruth::rebuild(const Scene&) { native(); }
bool GroundTruth::update(const Scene&, std::uint64_t) { native(); }
ImageF GroundTruth::hardVisibility(const SurfaceBuffer&, const Light&) const { native(); }
ImageF GroundTruth::softVisibility(const SurfaceBuffer&, const Light&, int, std::uint64_t) const { native(); }
bool GroundTruth::occluded(const glm::vec3&, const glm::vec3&, float) const { native(); }

}  // namespace shadowlab::measure
