#pragma once
// Which of the APIs' freedoms a back end takes, from the vectors that tell: for each freedom (the
// tie rule, the sub-pixel precision, the depth arithmetic, the 24-bit conversion) the kit's
// readings of it, and for each reading the pixels where its answer differs from the contract's
// and the back end sides with it, with the contract, or with neither. A reading the back end
// sides with and never against is the one it takes; the evidence is kept so a report can show
// it (vectors and pixels for and against).

#include <string>
#include <vector>

#include "recode/conformance/backend.hpp"
#include "recode/kit/variants.hpp"
#include "recode/raster/command_stream.hpp"

namespace recode::conformance {

// One reading of a freedom and the evidence for and against it.
struct FingerprintCandidate {
  kit::Variant variant = kit::Variant::Contract;  // Contract: the contract's own reading
  std::string name;                               // "contract", "top_left_fill", ...
  std::string what;                               // one line
  long long pixelsFor = 0;      // pixels where the back end gives this reading's values
  long long pixelsAgainst = 0;  // pixels where it gives another candidate's values instead
  long long pixelsNeither = 0;  // pixels where it gives none of the candidates' values
  std::vector<std::string> vectorsFor, vectorsAgainst;  // the first few of each
};

// One freedom: its candidates and the verdict.
struct FingerprintTrait {
  std::string freedom;  // "tie rule", "sub-pixel precision", "depth arithmetic", ...
  std::vector<FingerprintCandidate> candidates;
  // The candidate with evidence for it and none against (the most pixels for, if several),
  // else -1: the vectors do not tell, or no reading of the kit matches.
  int taken = -1;
  // "top_left_fill: left and top edges own their samples (for 120 pixels in 14 vectors, against
  // 0)" or "undetermined: ..." / "none of the kit's readings: ...".
  [[nodiscard]] std::string verdict() const;
};

// A back end's fingerprint, built one vector at a time.
class FingerprintBuilder {
 public:
  FingerprintBuilder();
  // Adds the evidence of one vector the back end answered (a refusal tells nothing).
  void add(const std::string& name, const raster::CommandStream& stream, const Answer& expected,
           const Answer& got);
  // The traits as they stand.
  [[nodiscard]] const std::vector<FingerprintTrait>& traits() const { return traits_; }

 private:
  std::vector<FingerprintTrait> traits_;
};

// The fingerprint as lines for the terminal report ("fingerprint:" and one line per trait).
[[nodiscard]] std::string describe(const std::vector<FingerprintTrait>& traits);

}  // namespace recode::conformance
