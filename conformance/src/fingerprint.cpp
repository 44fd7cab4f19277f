#include "recode/conformance/fingerprint.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>

#include "recode/conformance/api_freedoms.hpp"

namespace recode::conformance {

namespace {

// Vectors named per candidate and side: enough to find them, few enough to read.
constexpr std::size_t kVectorsNamed = 5;

enum class Buffers { StencilFirst, Depth };

struct TraitSpec {
  const char* freedom;
  const char* contractWhat;
  Freedom of;
  Buffers buffers;  // coverage traits judge by the stencil, where it differs
};

constexpr TraitSpec kTraits[] = {
    {"tie rule", "left and bottom edges own the samples on them", Freedom::TieRule,
     Buffers::StencilFirst},
    {"sub-pixel precision", "vertices on the 1/256-pixel grid (8 bits)", Freedom::SubPixelPrecision,
     Buffers::StencilFirst},
    {"depth arithmetic", "the plane in double, in the contract's order",
     Freedom::DepthInterpolation, Buffers::Depth},
    {"24-bit conversion", "z * 16777215 rounded to nearest, ties to even", Freedom::DepthConversion,
     Buffers::Depth},
};

void note(std::vector<std::string>& names, const std::string& name) {
  if (names.size() < kVectorsNamed && (names.empty() || names.back() != name))
    names.push_back(name);
}

// Every candidate's answer to the stream, trait by trait, the contract's first.
std::vector<std::vector<Answer>> candidateAnswers(const std::vector<FingerprintTrait>& traits,
                                                  const raster::CommandStream& stream,
                                                  const Answer& expected) {
  std::vector<std::vector<Answer>> all(traits.size());
  for (std::size_t ti = 0; ti < traits.size(); ++ti) {
    all[ti].push_back(expected);
    for (std::size_t c = 1; c < traits[ti].candidates.size(); ++c)
      all[ti].push_back(ModelBackend(traits[ti].candidates[c].variant).run(stream));
  }
  return all;
}

// Whether some candidate covers other samples than the contract at pixel p.
bool coverageMoves(const std::vector<Answer>& answers, const Answer& expected, std::size_t p) {
  return std::any_of(answers.begin(), answers.end(), [&](const Answer& a) {
    return !a.wasRefused() && a.stencil[p] != expected.stencil[p];
  });
}

// The buffer pixel p tells a trait by: the stencil where a candidate's stencil differs (coverage
// traits), else the depth; nullopt where the pixel tells nothing of the trait: no candidate
// differs there, or a coverage trait's candidates differ in depth only (the back end's depth
// arithmetic would speak instead of its coverage).
std::optional<bool> judgedByStencil(const std::vector<Answer>& answers, bool stencilFirst,
                                    std::size_t p) {
  const Answer& expected = answers.front();
  bool byStencil = false;
  bool differs = false;
  for (std::size_t c = 1; c < answers.size(); ++c) {
    if (answers[c].wasRefused())
      continue;
    if (stencilFirst && answers[c].stencil[p] != expected.stencil[p])
      byStencil = true;
    if (answers[c].depth[p] != expected.depth[p] || answers[c].stencil[p] != expected.stencil[p])
      differs = true;
  }
  if (!differs || (stencilFirst && !byStencil))
    return std::nullopt;
  return byStencil;
}

// A pixel tells about one freedom only where no other coverage freedom moves it: a pipeline
// with another tie rule and another grid would otherwise count against both.
bool confounded(const std::vector<std::vector<Answer>>& all, std::size_t ti, std::size_t p) {
  for (std::size_t other = 0; other < all.size(); ++other) {
    if (other != ti && kTraits[other].buffers == Buffers::StencilFirst &&
        coverageMoves(all[other], all[other].front(), p))
      return true;
  }
  return false;
}

// Counts pixel p for or against each candidate of the trait: for where the back end gives its
// value, against where it gives another candidate's, neither where it gives none of theirs.
void tally(FingerprintTrait& trait, const std::vector<Answer>& answers, const Answer& got,
           bool byStencil, std::size_t p, const std::string& name) {
  const auto value = [&](const Answer& a) -> std::uint32_t {
    return byStencil ? a.stencil[p] : a.depth[p];
  };
  const std::uint32_t mine = value(got);
  const std::uint32_t contract = value(answers.front());
  for (std::size_t c = 0; c < answers.size(); ++c) {
    if (answers[c].wasRefused())
      continue;
    const std::uint32_t theirs = value(answers[c]);
    // Only the pixels where this candidate stands apart from the contract tell about it; for
    // the contract, the pixels where any reading does.
    if (c != 0 && theirs == contract)
      continue;
    FingerprintCandidate& cand = trait.candidates[c];
    if (mine == theirs) {
      ++cand.pixelsFor;
      note(cand.vectorsFor, name);
      continue;
    }
    const bool other = std::any_of(answers.begin(), answers.end(), [&](const Answer& a) {
      return !a.wasRefused() && value(a) == mine;
    });
    if (other) {
      ++cand.pixelsAgainst;
      note(cand.vectorsAgainst, name);
    } else {
      ++cand.pixelsNeither;
    }
  }
}

// The candidate taken: sided with, never against, and more often than the back end sides with
// none of the readings anywhere the trait tells (the contract's "neither" counts those pixels);
// -1 if none is.
int takenCandidate(const FingerprintTrait& trait) {
  int taken = -1;
  long long best = 0;
  for (std::size_t c = 0; c < trait.candidates.size(); ++c) {
    const FingerprintCandidate& cand = trait.candidates[c];
    if (cand.pixelsAgainst == 0 && cand.pixelsFor > best &&
        cand.pixelsFor > trait.candidates.front().pixelsNeither) {
      best = cand.pixelsFor;
      taken = static_cast<int>(c);
    }
  }
  return taken;
}

}  // namespace

FingerprintBuilder::FingerprintBuilder() {
  std::vector<kit::VariantInfo> readings(kit::wrongVariants().begin(), kit::wrongVariants().end());
  readings.insert(readings.end(), kit::subPixelVariants().begin(), kit::subPixelVariants().end());
  for (const TraitSpec& spec : kTraits) {
    FingerprintTrait t;
    t.freedom = spec.freedom;
    t.candidates.push_back(
        {kit::Variant::Contract, "contract", spec.contractWhat, 0, 0, 0, {}, {}});
    for (const kit::VariantInfo& r : readings) {
      if (freedomOf(r.variant) == spec.of)
        t.candidates.push_back(
            {r.variant, std::string(r.name), std::string(r.what), 0, 0, 0, {}, {}});
    }
    traits_.push_back(std::move(t));
  }
}

void FingerprintBuilder::add(const std::string& name, const raster::CommandStream& stream,
                             const Answer& expected, const Answer& got) {
  if (got.wasRefused() || expected.wasRefused())
    return;
  const std::size_t n = expected.depth.size();
  if (got.depth.size() != n || got.stencil.size() != n)
    return;
  const std::vector<std::vector<Answer>> all = candidateAnswers(traits_, stream, expected);
  for (std::size_t ti = 0; ti < traits_.size(); ++ti) {
    const bool stencilFirst = kTraits[ti].buffers == Buffers::StencilFirst;
    for (std::size_t p = 0; p < n; ++p) {
      const std::optional<bool> byStencil = judgedByStencil(all[ti], stencilFirst, p);
      if (byStencil && !confounded(all, ti, p))
        tally(traits_[ti], all[ti], got, *byStencil, p, name);
    }
    traits_[ti].taken = takenCandidate(traits_[ti]);
  }
}

std::string FingerprintTrait::verdict() const {
  const auto evidence = [](const FingerprintCandidate& c) {
    return "for " + std::to_string(c.pixelsFor) + " pixels, against " +
           std::to_string(c.pixelsAgainst) + ", neither " + std::to_string(c.pixelsNeither);
  };
  if (taken >= 0) {
    const FingerprintCandidate& c = candidates[static_cast<std::size_t>(taken)];
    return c.name + ": " + c.what + " (" + evidence(c) + ")";
  }
  const auto most =
      std::max_element(candidates.begin(), candidates.end(),
                       [](const FingerprintCandidate& a, const FingerprintCandidate& b) {
                         return a.pixelsFor - a.pixelsAgainst < b.pixelsFor - b.pixelsAgainst;
                       });
  if (most == candidates.end() || most->pixelsFor == 0)
    return "not told: no vector shows the back end beside one of the kit's readings";
  return "none of the kit's readings on every pixel; closest " + most->name + " (" +
         evidence(*most) + ")";
}

std::string describe(const std::vector<FingerprintTrait>& traits) {
  std::string out = "fingerprint (the freedoms of the graphics APIs it takes):\n";
  for (const FingerprintTrait& t : traits)
    out += "  " + t.freedom + ": " + t.verdict() + "\n";
  return out;
}

}  // namespace recode::conformance
