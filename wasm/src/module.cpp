// The functions the WebAssembly module exports (docs/wasm.md). Each takes a request as text
// and returns its answer as text that stays valid until the next call, or null on an error,
// whose message recode_error() then returns. Nothing throws across the boundary.
#include <emscripten/emscripten.h>

#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

#include "golden_check.hpp"
#include "gpu_commands.hpp"
#include "live_page.hpp"
#include "output/pgm.hpp"
#include "pair_request.hpp"
#include "recode/raster/cpu_device.hpp"

namespace {

std::string lastAnswer;
std::string lastError;
recode::wasm::LivePage lastPage;  // its pictures stay in memory until the next page

template <class F>
const char* answer(F run) {
  try {
    lastError.clear();
    lastAnswer = run();
    return lastAnswer.c_str();
  } catch (const std::exception& e) {
    lastError = e.what();
  } catch (...) {
    lastError = "unknown error";
  }
  return nullptr;
}

}  // namespace

extern "C" {

// `recode pair --json` for the request (pair_request.hpp): the same bytes, "\n" included; with
// "dump_cases", the case map written as `--dump-cases` writes it.
EMSCRIPTEN_KEEPALIVE const char* recode_pair(const char* request) {
  return answer([&] {
    const recode::wasm::PairRequestText r = recode::wasm::readPairRequest(request);
    const recode::explain::PairRun run =
        recode::explain::runPair(r.options, [](int width, int height) {
          return std::make_unique<recode::raster::CpuDevice>(width, height);
        });
    if (!r.dumpCases.empty() && run.layered)
      throw std::invalid_argument(
          "dump_cases writes RECODE's cases 0-8, which a pair with a "
          "closed mesh does not have");
    if (!r.dumpCases.empty())
      recode::output::writePgmBottomUp(
          r.dumpCases, run.setup.frame.width, run.setup.frame.height,
          recode::explain::frameCaseImage(run.setup.frame, run.result));
    return recode::explain::pairRunJson(run, !r.timing).dump(2) + "\n";
  });
}

// The interactive page's view of the request (live_page.hpp); its pictures stay valid until
// the next call of recode_page.
EMSCRIPTEN_KEEPALIVE const char* recode_page(const char* request) {
  return answer([&] {
    lastPage = recode::wasm::livePage(recode::wasm::readPairRequest(request));
    return lastPage.json;
  });
}

// The golden vector at `path` replayed on the CPU device and compared with its expected
// buffers (golden_check.hpp).
EMSCRIPTEN_KEEPALIVE const char* recode_check_golden(const char* path) {
  return answer([&] { return recode::wasm::checkGolden(path); });
}

// The golden vector at `path` as a GPU back end replays it: proxy records, render states and
// the expected buffers (gpu_commands.hpp).
EMSCRIPTEN_KEEPALIVE const char* recode_gpu_commands(const char* path) {
  return answer([&] { return recode::wasm::gpuCommands(path); });
}

// The message of the last call that returned null.
EMSCRIPTEN_KEEPALIVE const char* recode_error() {
  return lastError.c_str();
}

}  // extern "C"
