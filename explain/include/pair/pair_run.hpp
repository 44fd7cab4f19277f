#pragma once
// One run of `recode pair`, apart from its command line: the setup, the reference run, the
// --mode decision, the --pixel probe, and the JSON of docs/cli.md. The command and the
// WebAssembly module (wasm/) both run this, so that their outputs are the same bytes.

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>

#include "pair/pair_report.hpp"
#include "pair/pair_setup.hpp"
#include "recode/pair/layered_pair.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/device.hpp"
#include "recode/refine/pair_mode.hpp"
#include "recode/refine/view_axis_choice.hpp"

namespace recode::explain {

struct PairRunOptions {
  std::optional<std::string> scene;  // a scene file; none: the built-in pair
  core::FrameOverrides overrides;    // --resolution, --pixel-size
  core::MorMode mor = core::MorMode::Min;
  bool contact = true;  // false: --no-contact
  bool boxTest = true;  // false: --no-box-test
  bool normal = false;  // --normal
  std::string pixel;    // --pixel X,Y; empty: none
  core::PairMode mode = core::PairMode::Reference;
  core::ViewAxisRule axisRule = core::ViewAxisRule::Scene;
};

// A fresh width x height device to draw the pair on.
using PairDeviceMaker =
    std::function<std::unique_ptr<raster::DepthStencilDevice>(int width, int height)>;

struct PairRun {
  PairSetup setup;  // its frame along the axis the rule chose
  core::PairRequest request;
  core::PairResult result;                         // RECODE's passes (empty for a layered pair)
  std::optional<core::LayeredPairResult> layered;  // when either object is a closed mesh
  core::ViewAxisRule axisRule = core::ViewAxisRule::Scene;
  std::optional<nlohmann::ordered_json> modeReport;  // when the mode is not the reference
  std::optional<PixelProbe> probe;                   // when a pixel was asked for
};

// Runs the pair as `recode pair` does. `observer`, when given, sees every step of the
// reference run (beside the pixel probe). Throws what loading the scene throws, and
// std::invalid_argument for a --pixel outside the frame (naming the option and the rule), and
// for --pixel, --mode or --view-axis on a pair with a closed mesh (RECODE's passes alone have
// them).
[[nodiscard]] PairRun runPair(const PairRunOptions& options, const PairDeviceMaker& makeDevice,
                              core::PairObserver* observer = nullptr);

// The object `recode pair --json` prints; without the wall-clock fields when noTiming.
[[nodiscard]] nlohmann::ordered_json pairRunJson(const PairRun& run, bool noTiming);

// The report `recode pair` prints without --json.
void printPairRun(std::ostream& out, const PairRun& run, bool picture);

}  // namespace recode::explain
