#pragma once
// The conformance suite in a Catch2 v2 test program: a back end's author checks their own
// raster::DepthStencilDevice against RECODE's golden vectors with CHECK_THAT, and a failing
// check's message is the suite's report (the stage at which the device departs from the
// contract, a few bad pixels explained with their histories, the reading it behaves like).
// Header-only: recode::conformance does not depend on Catch2; the test program links both.
//
// CMake, with the installed package (or add_subdirectory of RECODE's source tree, which sets
// the same variable):
//   find_package(recode 0.1 REQUIRED COMPONENTS conformance)
//   find_package(Catch2 2 REQUIRED)
//   add_executable(device_conformance device_conformance.cpp)
//   target_link_libraries(device_conformance PRIVATE recode::conformance Catch2::Catch2WithMain)
//   target_compile_definitions(device_conformance PRIVATE
//                              RECODE_GOLDEN_DIR="${RECODE_GOLDEN_DIR}")
//
// device_conformance.cpp:
//   #include "recode/conformance/catch2.hpp"
//   #include "my_device.hpp"  // class MyDevice : public recode::raster::DepthStencilDevice
//
//   using namespace recode::conformance;
//
//   DeviceBackend myDevice() {
//     return DeviceBackend("my device", [](int width, int height) {
//       return std::make_unique<MyDevice>(width, height);
//     });
//   }
//
//   // One section per golden vector: each vector passes or fails on its own, named.
//   TEST_CASE("my device passes every golden vector") {
//     DeviceBackend device = myDevice();
//     const SuiteVector& v = GENERATE(eachGoldenVector(RECODE_GOLDEN_DIR));
//     DYNAMIC_SECTION(v.name) { CHECK_THAT(device, ConformsTo(v)); }
//   }
//
//   // The whole suite in one check: on failure, also the kit's wrong reading that the device
//   // behaves like on every vector ("behaves like: INCR wraps 255 to 0 ..."), if one does.
//   TEST_CASE("my device passes the golden suite") {
//     DeviceBackend device = myDevice();
//     CHECK_THAT(device, ConformsTo(goldenVectors(RECODE_GOLDEN_DIR)));
//   }
//
// Any Backend matches (backend.hpp): a DeviceBackend, a ProcessBackend (a program speaking the
// line protocol), a ModelBackend. The matcher runs it: Catch hands a matcher its argument as
// const, and the run is not, so the backend must not be an object defined const. A
// BackendError (a process that crashed or hung) fails the check with the error; any other
// exception from the device fails it as Catch's unexpected exception.

#include <catch2/catch.hpp>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "recode/conformance/backend.hpp"
#include "recode/conformance/report.hpp"
#include "recode/conformance/suite.hpp"

namespace recode::conformance {

// A Catch matcher: the backend gives every vector's expected buffers. Its description, printed
// when the check fails, is the suite's report of the failing vectors.
class ConformsToMatcher final : public Catch::MatcherBase<Backend> {
 public:
  // `explained`: bad pixels explained per failing vector; `shownVectors`: failing vectors
  // reported in full (the rest are counted).
  ConformsToMatcher(std::vector<SuiteVector> vectors, std::size_t explained,
                    std::size_t shownVectors)
      : vectors_(std::move(vectors)), explained_(explained), shownVectors_(shownVectors) {}

  bool match(const Backend& backend) const override {
    SuiteOptions options;
    options.explainLimit = explained_;
    options.nameReadings = vectors_.size() > 1;  // one vector is too little to name a reading
    const SuiteReport report = runSuite(const_cast<Backend&>(backend), vectors_, options);
    report_ = "conforms to " + what();
    if (report.passed())
      return true;
    std::ostringstream out;
    out << ", but:\n";
    std::size_t failing = 0;
    for (const VectorReport& v : report.vectors) {
      if (failsRun(v.status) && ++failing <= shownVectors_)
        printVector(out, v, explained_);
    }
    if (failing > shownVectors_)
      out << "  (" << failing - shownVectors_ << " more failing vectors)\n";
    if (vectors_.size() > 1) {
      out << failing << " of " << report.vectors.size() << " vectors fail";
      if (const std::string v = verdict(report); !v.empty())
        out << "; " << v;
      out << '\n';
    }
    if (!report.error.empty()) {
      out << "the back end failed to answer";
      if (report.errorKind)
        out << " (" << recode::conformance::toString(*report.errorKind) << ")";
      out << ": " << report.error << '\n';
    }
    report_ += out.str();
    report_.pop_back();  // the last '\n'
    return false;
  }

  std::string describe() const override {
    return report_.empty() ? "conforms to " + what() : report_;
  }

 private:
  std::string what() const {
    if (vectors_.size() == 1)
      return "golden vector " + vectors_.front().name;
    return std::to_string(vectors_.size()) + " golden vectors";
  }

  std::vector<SuiteVector> vectors_;
  std::size_t explained_;
  std::size_t shownVectors_;
  mutable std::string report_;  // match() writes it, Catch reads it after (describe)
};

// The backend's answer to `vector` equals its expected buffers. On failure the message is the
// vector's report (suite.hpp, report.hpp) with `explained` bad pixels explained.
[[nodiscard]] inline ConformsToMatcher ConformsTo(const SuiteVector& vector,
                                                  std::size_t explained = 2) {
  return ConformsToMatcher({vector}, explained, 1);
}

// The backend passes every vector (e.g. goldenVectors(dir)). On failure the message is the run's
// report: the first `shownVectors` failing vectors with `explained` bad pixels each, the counts
// and the verdict (report.hpp: the reading the backend behaves like, or the stages).
[[nodiscard]] inline ConformsToMatcher ConformsTo(std::vector<SuiteVector> vectors,
                                                  std::size_t explained = 1,
                                                  std::size_t shownVectors = 3) {
  return ConformsToMatcher(std::move(vectors), explained, shownVectors);
}

// A Catch generator of the golden vectors under `dir` (goldenVectors: every *.json, sorted by
// name), for GENERATE: the files are read once, when the test case first reaches it.
class GoldenVectorGenerator final : public Catch::Generators::IGenerator<SuiteVector> {
 public:
  explicit GoldenVectorGenerator(const std::filesystem::path& dir) : vectors_(goldenVectors(dir)) {}
  const SuiteVector& get() const override { return vectors_[index_]; }
  bool next() override { return ++index_ < vectors_.size(); }

 private:
  std::vector<SuiteVector> vectors_;  // never empty: goldenVectors throws for no vectors
  std::size_t index_ = 0;
};

[[nodiscard]] inline Catch::Generators::GeneratorWrapper<SuiteVector> eachGoldenVector(
    const std::filesystem::path& dir) {
  return Catch::Generators::GeneratorWrapper<SuiteVector>(
      std::make_unique<GoldenVectorGenerator>(dir));
}

}  // namespace recode::conformance

// A backend in Catch's messages: its name.
namespace Catch {
template <typename T>
struct StringMaker<T, std::enable_if_t<std::is_base_of_v<recode::conformance::Backend, T>>> {
  static std::string convert(const T& backend) { return "back end \"" + backend.name() + "\""; }
};
}  // namespace Catch
