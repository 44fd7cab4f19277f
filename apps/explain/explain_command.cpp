// `recode explain`: its command-line options; the pages are written by the explain library
// (explain/).
#include "explain/explain_command.hpp"

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "explain/explain_gallery.hpp"
#include "explain/explain_hierarchy.hpp"
#include "explain/explain_recorder.hpp"
#include "explain/interactive_page.hpp"
#include "explain/static_page.hpp"
#include "explain/wasm_module_asset.hpp"
#include "output/atomic_file.hpp"
#include "pair/pair_setup.hpp"
#include "recode/io/printable.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/pair.hpp"

namespace recode::app {

namespace {

namespace fs = std::filesystem;

struct ExplainOptions {
  std::string scene;  // empty: the built-in pair
  std::string out;
  std::string mor = "min";
  std::string resolution;
  bool boxTest = true;
  bool gallery = false;
  bool interactive = false;  // --interactive: the page that runs the reference in the browser
  std::string pair;          // --pair NAME_A:NAME_B; empty: the scene's first two objects
  int frame = 0;             // --frame K, with --pair
};

// The WebAssembly module the interactive page runs, embedded at build time; a build without
// emscripten has none and says what to install.
std::string_view interactiveModule() {
#if RECODE_HAVE_WASM_MODULE
  return kRecodeWasmJs;
#else
  throw std::runtime_error(
      "this build has no WebAssembly module for the interactive page: install emscripten "
      "(apt-get install emscripten, or scripts/setup.sh) and rebuild (RECODE_WITH_WASM)");
#endif
}

int runExplain(const ExplainOptions& options) {
  if (options.interactive) {
    const fs::path dir(options.out);
    // Removed again if the page cannot be written (a build without the module included).
    output::CreatedDirectory created(dir, "--out " + options.out);
    explain::writeInteractivePage(dir, interactiveModule());
    created.keep();
    std::cout << "recode explain --interactive: wrote " << (dir / "index.html").string()
              << " (open it in a browser; it runs the reference in WebAssembly)\n";
    return 0;
  }
  if (options.gallery) {
    if (!options.scene.empty())
      throw std::invalid_argument("--gallery runs its own pairs; leave out the scene " +
                                  options.scene);
    const core::FrameOverrides overrides = options.resolution.empty()
                                               ? core::FrameOverrides{}
                                               : explain::parseResolution(options.resolution);
    const fs::path dir(options.out);
    output::CreatedDirectory created(dir, "--out " + options.out);
    const std::size_t pages = explain::writeGallery(dir, overrides);
    created.keep();
    std::cout << "recode explain --gallery: wrote " << pages << " pages and index.html to "
              << dir.string() << '\n';
    return 0;
  }
  const core::FrameOverrides overrides = options.resolution.empty()
                                             ? core::FrameOverrides{}
                                             : explain::parseResolution(options.resolution);
  explain::HierarchyPair chosen;
  if (!options.pair.empty()) {
    if (options.scene.empty())
      throw std::invalid_argument("--pair " + options.pair + ": needs a scene file");
    chosen = explain::hierarchyPair(options.scene, options.frame, options.pair, overrides);
  } else {
    chosen.setup = explain::loadPairSetup(
        options.scene.empty() ? std::nullopt : std::optional<std::string>(options.scene),
        overrides);
  }
  const explain::PairSetup& setup = chosen.setup;
  if (setup.layered())
    throw std::invalid_argument(
        "recode explain shows RECODE's passes on two convex blocks; this pair has a closed mesh "
        "(recode pair decides it by layers, docs/algorithm.md section 13)");
  const core::FrameSpec& f = setup.frame;
  // Removed again, with what was written into it, if anything below fails.
  const fs::path dir(options.out);
  output::CreatedDirectory created(dir, "--out " + options.out);
  const explain::ExplainSummary summary =
      explain::explainPairInto(setup, options.mor, options.boxTest, dir, chosen.descentHtml);
  const core::PairResult& result = summary.result;
  created.keep();
  const std::size_t written = summary.pictures;
  std::cout << "recode explain: " << io::printable(setup.nameA) << " and "
            << io::printable(setup.nameB) << ", " << f.width << "x" << f.height << " pixels along "
            << core::toString(f.axis) << ", MOR " << options.mor << ": "
            << (result.collide ? "collide" : "no collision") << " (" << result.interferingPixels
            << " interfering pixels)\n"
            << "  wrote " << written << (written == 1 ? " picture" : " pictures")
            << ", index.html and explain.json to " << dir.string() << '\n';
  return 0;
}

}  // namespace

void addExplainCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<ExplainOptions>();
  CLI::App* cmd = app.add_subcommand(
      "explain",
      "Run RECODE on one pair and write a picture of the buffers after every step, with an "
      "index.html that explains each step");
  cmd->add_option("scene", opts->scene,
                  "scene file (JSON, docs/scenes.md; its first two objects are A and B); omit "
                  "for the built-in pair")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", opts->out,
                  "directory for the pictures, index.html and explain.json "
                  "(created if missing)")
      ->required();
  cmd->add_option("--mor", opts->mor, "minimum overlapping region: min, max or full")
      ->check(CLI::IsMember({"min", "max", "full"}))
      ->capture_default_str();
  cmd->add_option("--resolution", opts->resolution,
                  "W or WxH pixels (W alone: square pixels); overrides the scene; at most " +
                      std::to_string(explain::kMaxExplainSide) + " a side");
  cmd->add_flag("!--no-box-test", opts->boxTest,
                "run the passes even when the blocks' boxes are apart (shows cases 1, 2, 7, 8)");
  CLI::Option* pair = cmd->add_option(
      "--pair", opts->pair,
      "NAME_A:NAME_B: two blocks of the scene's objects (paths like 'dumbbell/bar', or names "
      "when unique), for scenes whose objects have children; adds the box descent");
  cmd->add_option("--frame", opts->frame, "with --pair: the frame to pose the scene at")
      ->needs(pair)
      ->capture_default_str();
  cmd->add_flag("--gallery", opts->gallery,
                "write one page per case 1-8 from small built-in pairs, and a pair that is "
                "apart, with an index.html linking them (no scene; --mor and --no-box-test "
                "are chosen per pair)");
  cmd->add_flag("--interactive", opts->interactive,
                "write one self-contained page (index.html) on which two blocks can be shaped, "
                "dragged and turned, every step recomputed in the browser by the reference "
                "compiled to WebAssembly, with a 3-D view of the blocks and exercises that "
                "check a student's prediction of every pass (docs/wasm.md)")
      ->excludes(cmd->get_option("scene"))
      ->excludes(cmd->get_option("--pair"))
      ->excludes(cmd->get_option("--gallery"))
      ->excludes(cmd->get_option("--resolution"))
      ->excludes(cmd->get_option("--no-box-test"));
  cmd->callback([opts, &exitCode]() { exitCode = runExplain(*opts); });
}

}  // namespace recode::app
