#pragma once
// One pair of convex blocks run through RECODE and then through every selected oracle, and the
// totals over many pairs: what `recode verify` prints and what the suites assert. Which oracles
// exist depends on the build (RECODE_WITH_EMBREE / _CGAL / _OSMESA); asking for one that was not
// built is an error, never a silent skip.

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/pair.hpp"
#include "recode/verify/cgal_oracle.hpp"
#include "recode/verify/embree_oracle.hpp"
#include "recode/verify/exact_parity.hpp"
#include "recode/verify/gl_parity.hpp"

namespace recode::verify {

enum class Oracle { Embree, Cgal, Gl, GlExact, Vulkan };
// "embree", "cgal", "gl", "gl-exact", "vulkan"
[[nodiscard]] std::string_view toString(Oracle oracle);
// Whether this build contains the oracle.
[[nodiscard]] bool oracleBuilt(Oracle oracle);

struct OracleSelection {
  bool embree = false;
  bool cgal = false;
  bool gl = false;
  bool glExact = false;  // bit-exact replay on backends::GlExactDevice
  backends::GlPlatform glPlatform = backends::GlPlatform::Auto;  // its context platform
  bool vulkan = false;  // bit-exact replay on backends::VulkanDevice
  // With vulkan: which Vulkan device (the vulkan-32 device's 32-bit shader arithmetic, or the
  // vulkan-compute device, instead of the vulkan device); the reports keep the key "vulkan".
  VulkanOracleDevice vulkanDevice = VulkanOracleDevice::Native64;
};

struct PairVerification {
  std::string label;
  core::PairResult result;  // RECODE on raster::CpuDevice
  std::optional<EmbreeReport> embree;
  std::optional<ExactIntersection> exact;
  std::optional<CgalJudgement> cgal;
  std::optional<GlParityReport> gl;
  std::optional<ExactParityReport> glExact;
  std::optional<ExactParityReport> vulkan;
  double embreeSeconds = 0.0;  // wall time of each oracle on this pair
  double cgalSeconds = 0.0;
  double glSeconds = 0.0;
  double glExactSeconds = 0.0;
  double vulkanSeconds = 0.0;

  // No unexplained pixel, no CGAL disagreement, no unexplained GL difference, no pixel of the
  // exact GL or Vulkan device different.
  [[nodiscard]] bool passed() const;
};

struct VerificationTotals {
  long long pairs = 0;
  long long failedPairs = 0;
  long long recodeCollisions = 0;
  EmbreeCounts embree;
  long long embreeRays = 0;
  CgalCounts cgal;
  GlParityCounts gl;
  ExactParityCounts glExact;
  ExactParityCounts vulkan;
  double embreeSeconds = 0.0;
  double cgalSeconds = 0.0;
  double glSeconds = 0.0;
  double glExactSeconds = 0.0;
  double vulkanSeconds = 0.0;

  void add(const PairVerification& pair);
  [[nodiscard]] bool passed() const { return failedPairs == 0; }
};

// Runs pairs through RECODE and the selected oracles, keeping each oracle's state (Embree's
// device) between pairs. Throws std::invalid_argument from the constructor when a selected
// oracle is not in this build.
class PairVerifier {
 public:
  explicit PairVerifier(const OracleSelection& selection);
  ~PairVerifier();
  PairVerifier(const PairVerifier&) = delete;
  PairVerifier& operator=(const PairVerifier&) = delete;

  [[nodiscard]] const OracleSelection& selection() const { return selection_; }

  // A and B in world coordinates; request.frame is the frame RECODE and the oracles use.
  [[nodiscard]] PairVerification verify(std::string label, const core::TriangleMesh& a,
                                        const core::TriangleMesh& b,
                                        const core::PairRequest& request);

 private:
  struct State;  // the oracles this build has (defined where the build options are known)
  OracleSelection selection_;
  std::unique_ptr<State> state_;
};

}  // namespace recode::verify
