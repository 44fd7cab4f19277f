// A back end in C++ over the recode-conform-1 line protocol (docs/conformance.md): the kit's
// independent reference model, run with the contract or with one of its wrong readings. It is
// what `recode conform --exec` drives in the tests (each wrong reading must be named), and a
// template for a back end of your own: replace ModelBackend with your device.
//
//   recode-model-backend [--variant NAME] [--flaky]
//     NAME: contract (default) or a reading of raster/kit/include/recode/kit/variants.hpp;
//     --flaky: every second answer has pixel 0's stencil inverted (a nondeterministic back end,
//     for the tests of `recode conform`'s nondeterministic status).
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "recode/conformance/backend.hpp"
#include "recode/kit/variants.hpp"
#include "recode/raster/golden.hpp"

namespace {

using nlohmann::json;
using recode::kit::Variant;

bool variantNamed(const std::string& name, Variant& out) {
  if (name == "contract") {
    out = Variant::Contract;
    return true;
  }
  for (const recode::kit::VariantInfo& v : recode::kit::wrongVariants()) {
    if (v.name == name) {
      out = v.variant;
      return true;
    }
  }
  return false;
}

// One request: the stream read as a command file (the same reader and errors as golden files).
json answer(const json& request, recode::conformance::Backend& backend) {
  const json doc = {{"format", "recode-commands-1"},
                    {"width", request.at("width")},
                    {"height", request.at("height")},
                    {"commands", request.at("commands")}};
  const recode::raster::CommandStream stream =
      recode::raster::commandStreamFromJson(doc.dump(), "request");
  const recode::conformance::Answer a = backend.run(stream);
  if (a.wasRefused())
    return {{"id", request.at("id")}, {"refused", a.refused}};
  return {{"id", request.at("id")}, {"depth", a.depth}, {"stencil", a.stencil}};
}

}  // namespace

int main(int argc, char** argv) {
  Variant variant = Variant::Contract;
  bool flaky = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--variant" && i + 1 < argc) {
      if (!variantNamed(argv[++i], variant)) {
        std::cerr << "recode-model-backend: unknown variant \"" << argv[i] << "\"\n";
        return 1;
      }
    } else if (arg == "--flaky") {
      flaky = true;
    } else {
      std::cerr << "usage: recode-model-backend [--variant NAME] [--flaky]\n";
      return 1;
    }
  }
  recode::conformance::ModelBackend backend(variant);
  std::string line;
  try {
    if (!std::getline(std::cin, line) ||
        json::parse(line).value("protocol", "") != "recode-conform-1")
      throw std::runtime_error("expected the greeting {\"protocol\":\"recode-conform-1\"}");
    std::cout << json{{"protocol", "recode-conform-1"}, {"name", backend.name()}}.dump() << '\n'
              << std::flush;
    for (long long n = 0; std::getline(std::cin, line); ++n) {
      json a = answer(json::parse(line), backend);
      if (flaky && n % 2 == 1 && a.contains("stencil"))
        a["stencil"][0] = 255 - a["stencil"][0].get<int>();
      std::cout << a.dump() << '\n' << std::flush;
    }
  } catch (const std::exception& e) {
    std::cerr << "recode-model-backend: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
