#pragma once
// RECODE as one of the bench's detectors (scene_detector.hpp): core::Simulation -- sort and
// sweep, box descent, the pair algorithm per leaf pair -- drawing on the CPU reference device,
// on fixed-function OpenGL (backends::GlDevice, llvmpipe) or on the exact GPU-API devices
// (backends::GlExactDevice, backends::VulkanDevice), so the bench compares them on the same work.

#include <memory>
#include <string>

#include "recode/backends/device_registry.hpp"
#include "recode/scene/scene.hpp"
#include "recode/sim/simulation.hpp"
#include "recode/verify/scene_detector.hpp"

namespace recode::verify {

class RecodeDetector final : public SceneDetector {
 public:
  // The simulation of `scene` with `options` (options.deviceFactory is replaced by
  // backends::warmDeviceFactory for every device but Cpu). Throws std::runtime_error for a device
  // this build lacks.
  RecodeDetector(const core::Scene& scene, core::RunOptions options, backends::DeviceKind device,
                 std::string name);

  [[nodiscard]] std::string name() const override { return name_; }

  // Poses and runs its own trees (built from the same scene, so node indices match the
  // caller's), outside the timer; collisionUs is FrameReport::collisionUs, which leaves out
  // posing and the making of devices.
  [[nodiscard]] Detection detect(const std::vector<core::ObjectTree>& objects, int frame) override;

  // The counters of the last frame detected (box tests, pair tests, pixels read: Table 1).
  [[nodiscard]] const core::FrameReport& lastReport() const { return last_; }
  [[nodiscard]] const core::Simulation& simulation() const { return simulation_; }

 private:
  core::Simulation simulation_;
  std::string name_;
  core::FrameReport last_;
};

}  // namespace recode::verify
