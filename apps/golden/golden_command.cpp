#include "golden/golden_command.hpp"

#include <cstdint>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "recode/kit/generator.hpp"

namespace recode::app {

namespace {

struct GenerateOptions {
  int count = 300;
  std::uint64_t seed = 1;
  std::string out;
};

int runGenerate(const GenerateOptions& o) {
  const std::vector<kit::KitVector> vectors = kit::generateKit(o.count, o.seed);
  const auto written = kit::writeKit(vectors, o.out);
  std::map<std::string, int> perFamily;
  for (const kit::KitVector& v : vectors)
    ++perFamily[v.family];
  std::cout << "recode golden generate: " << written.size() << " vectors (seed " << o.seed
            << ") in " << o.out << '\n';
  for (const kit::FamilyInfo& f : kit::kitFamilies()) {
    const auto it = perFamily.find(std::string(f.name));
    if (it != perFamily.end())
      std::cout << "  " << f.name << ": " << it->second << " (" << f.checks << ")\n";
  }
  return 0;
}

}  // namespace

void addGoldenCommand(CLI::App& app, int& exitCode) {
  CLI::App* golden =
      app.add_subcommand("golden", "Golden vectors for back-end authors (docs/rasterization.md)");
  golden->require_subcommand(1);
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* generate = golden->add_subcommand(
      "generate",
      "Write adversarial golden vectors (the conformance kit, docs/rasterization.md section 9), "
      "the same bytes for the same count and seed");
  generate->add_option("--count", o->count, "vectors to write")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  generate->add_option("--seed", o->seed, "seed of the vectors' random sources")
      ->capture_default_str();
  generate
      ->add_option("--out", o->out,
                   "directory to write <family>_<index>.json into (created; an earlier kit's "
                   "files there are replaced)")
      ->required();
  generate->callback([o, &exitCode]() { exitCode = runGenerate(*o); });
}

}  // namespace recode::app
