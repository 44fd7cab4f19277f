#include "recode/verify/verify_pair.hpp"

#include <chrono>
#include <stdexcept>

#include "recode/raster/cpu_device.hpp"

namespace recode::verify {

namespace {

[[maybe_unused]] double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string howToBuild(Oracle oracle) {
  switch (oracle) {
    case Oracle::Embree:
      return "install libembree-dev and configure with -DRECODE_WITH_EMBREE=ON";
    case Oracle::Cgal:
      return "install libcgal-dev and configure with -DRECODE_WITH_CGAL=ON";
    case Oracle::Gl:
      return "install libosmesa6-dev or libegl-dev and configure with -DRECODE_WITH_OSMESA=ON "
             "or -DRECODE_WITH_EGL=ON";
    case Oracle::GlExact:
      return "install libosmesa6-dev or libegl-dev and configure with -DRECODE_WITH_OSMESA=ON "
             "or -DRECODE_WITH_EGL=ON";
    case Oracle::Vulkan:
      return "install libvulkan-dev, glslang-tools and mesa-vulkan-drivers and configure with "
             "-DRECODE_WITH_VULKAN=ON";
  }
  return "?";
}

void requireBuilt(Oracle oracle) {
  if (!oracleBuilt(oracle))
    throw std::invalid_argument("the " + std::string(toString(oracle)) +
                                " oracle is not in this build: " + howToBuild(oracle));
}

}  // namespace

std::string_view toString(Oracle oracle) {
  switch (oracle) {
    case Oracle::Embree:
      return "embree";
    case Oracle::Cgal:
      return "cgal";
    case Oracle::Gl:
      return "gl";
    case Oracle::GlExact:
      return "gl-exact";
    case Oracle::Vulkan:
      return "vulkan";
  }
  return "unknown";
}

bool oracleBuilt(Oracle oracle) {
  switch (oracle) {
    case Oracle::Embree:
#ifdef RECODE_HAVE_EMBREE
      return true;
#else
      return false;
#endif
    case Oracle::Cgal:
#ifdef RECODE_HAVE_CGAL
      return true;
#else
      return false;
#endif
    case Oracle::Gl:
#ifdef RECODE_HAVE_GL_DEVICE
      return true;
#else
      return false;
#endif
    case Oracle::GlExact:
#ifdef RECODE_HAVE_GL_EXACT
      return true;
#else
      return false;
#endif
    case Oracle::Vulkan:
#ifdef RECODE_HAVE_VULKAN
      return true;
#else
      return false;
#endif
  }
  return false;
}

bool PairVerification::passed() const {
  if (embree && embree->counts.unexplained != 0)
    return false;
  if (cgal && cgal->verdict == VerdictCheck::Disagree)
    return false;
  if (gl && gl->counts.unexplained != 0)
    return false;
  if (glExact && !glExact->ok())
    return false;
  if (vulkan && !vulkan->ok())
    return false;
  return true;
}

void VerificationTotals::add(const PairVerification& pair) {
  ++pairs;
  failedPairs += pair.passed() ? 0 : 1;
  recodeCollisions += pair.result.collide ? 1 : 0;
  if (pair.embree) {
    embree += pair.embree->counts;
    embreeRays += pair.embree->rays;
  }
  if (pair.cgal)
    cgal.add(*pair.cgal);
  if (pair.gl)
    gl += pair.gl->counts;
  if (pair.glExact)
    glExact += pair.glExact->counts;
  if (pair.vulkan)
    vulkan += pair.vulkan->counts;
  embreeSeconds += pair.embreeSeconds;
  cgalSeconds += pair.cgalSeconds;
  glSeconds += pair.glSeconds;
  glExactSeconds += pair.glExactSeconds;
  vulkanSeconds += pair.vulkanSeconds;
}

struct PairVerifier::State {
#ifdef RECODE_HAVE_EMBREE
  std::optional<EmbreeOracle> embree;
#endif
};

PairVerifier::PairVerifier(const OracleSelection& selection)
    : selection_(selection), state_(std::make_unique<State>()) {
  if (selection_.embree)
    requireBuilt(Oracle::Embree);
  if (selection_.cgal)
    requireBuilt(Oracle::Cgal);
  if (selection_.gl)
    requireBuilt(Oracle::Gl);
  if (selection_.glExact)
    requireBuilt(Oracle::GlExact);
  if (selection_.vulkan)
    requireBuilt(Oracle::Vulkan);
#ifdef RECODE_HAVE_EMBREE
  if (selection_.embree)
    state_->embree.emplace();
#endif
}

PairVerifier::~PairVerifier() = default;

PairVerification PairVerifier::verify(std::string label, const core::TriangleMesh& a,
                                      const core::TriangleMesh& b,
                                      const core::PairRequest& request) {
  PairVerification out;
  out.label = std::move(label);
  raster::CpuDevice device(request.frame.width, request.frame.height);
  out.result = core::collidePair(device, a, b, request);
#ifdef RECODE_HAVE_EMBREE
  if (state_->embree) {
    const auto start = std::chrono::steady_clock::now();
    out.embree = state_->embree->check(request.frame, a, b, out.result);
    out.embreeSeconds = secondsSince(start);
  }
#endif
#ifdef RECODE_HAVE_CGAL
  if (selection_.cgal) {
    const auto start = std::chrono::steady_clock::now();
    out.exact = exactIntersection(a, b);
    out.cgal = judgePair(*out.exact, request.frame, a, b, out.result);
    out.cgalSeconds = secondsSince(start);
  }
#endif
#ifdef RECODE_HAVE_GL_DEVICE
  if (selection_.gl) {
    const auto start = std::chrono::steady_clock::now();
    GlParityOptions options;
    options.platform = selection_.glPlatform;
    out.gl = compareOnGl(a, b, request, options);
    out.glSeconds = secondsSince(start);
  }
#endif
#ifdef RECODE_HAVE_GL_EXACT
  if (selection_.glExact) {
    const auto start = std::chrono::steady_clock::now();
    out.glExact = compareOnGlExact(a, b, request, selection_.glPlatform);
    out.glExactSeconds = secondsSince(start);
  }
#endif
#ifdef RECODE_HAVE_VULKAN
  if (selection_.vulkan) {
    const auto start = std::chrono::steady_clock::now();
    out.vulkan = compareOnVulkan(a, b, request, selection_.vulkanDevice);
    out.vulkanSeconds = secondsSince(start);
  }
#endif
  return out;
}

}  // namespace recode::verify
