// A back end's author's conformance tests, out of RECODE's tree: their own DepthStencilDevice
// (here one that forwards to the CPU reference device, with one deliberate bug to switch on)
// run through the whole golden suite with recode/conformance/catch2.hpp. Built by
// tests/package/installed (find_package(recode COMPONENTS conformance)) and
// tests/package/subdirectory (add_subdirectory), RECODE_GOLDEN_DIR defined by each.
// Run plainly it must pass; `[broken]` runs the buggy device, which must fail with the suite's
// report naming the stage and the reading (tests/package/check_consumer.cmake).
#include <memory>
#include <string>

#include "recode/conformance/catch2.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/forwarding_device.hpp"

namespace {

using recode::conformance::ConformsTo;
using recode::conformance::DeviceBackend;
using recode::conformance::SuiteVector;
namespace raster = recode::raster;

// The user's device. With `incrWraps` it has a bug: INCR wraps 255 to 0 like INCR_WRAP
// instead of saturating.
class UserDevice final : public raster::ForwardingDevice {
 public:
  UserDevice(int width, int height, bool incrWraps)
      : ForwardingDevice(std::make_unique<raster::CpuDevice>(width, height)),
        incrWraps_(incrWraps) {}

  void setStencilOps(raster::Face face, const raster::StencilOps& ops) override {
    raster::StencilOps sent = ops;
    if (incrWraps_) {
      for (raster::StencilOp* op : {&sent.stencilFail, &sent.depthFail, &sent.depthPass}) {
        if (*op == raster::StencilOp::Incr)
          *op = raster::StencilOp::IncrWrap;
      }
    }
    ForwardingDevice::setStencilOps(face, sent);
  }

 private:
  bool incrWraps_;
};

DeviceBackend userBackend(bool incrWraps) {
  return DeviceBackend(incrWraps ? "user device, INCR wrapping" : "user device",
                       [incrWraps](int width, int height) {
                         return std::make_unique<UserDevice>(width, height, incrWraps);
                       });
}

}  // namespace

TEST_CASE("the user's device passes every golden vector") {
  DeviceBackend device = userBackend(false);
  const SuiteVector& v = GENERATE(recode::conformance::eachGoldenVector(RECODE_GOLDEN_DIR));
  DYNAMIC_SECTION(v.name) {
    CHECK_THAT(device, ConformsTo(v));
  }
}

// Hidden: run with `[broken]`, where it must fail.
TEST_CASE("the user's device with INCR wrapping passes the golden suite", "[.broken]") {
  DeviceBackend device = userBackend(true);
  CHECK_THAT(device, ConformsTo(recode::conformance::goldenVectors(RECODE_GOLDEN_DIR)));
}
