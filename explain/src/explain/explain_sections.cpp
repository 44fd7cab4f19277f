#include "explain/explain_sections.hpp"

#include <cstdint>
#include <utility>

#include "explain/explain_text.hpp"

namespace recode::explain {

namespace {

using core::PairStep;

// Which buffers a step is about (a buffer that changed is pictured as well).
bool stepWritesDepth(PairStep s) {
  return s == PairStep::SetZ || s == PairStep::LoadAmin || s == PairStep::ContactNear ||
         s == PairStep::ContactFar;
}
bool stepWritesStencil(PairStep s) {
  return s == PairStep::SetZ || s == PairStep::TestZ || s == PairStep::TestAminFront ||
         s == PairStep::TestAminBack;
}

// The depth a step clears to inside its rectangle (docs/algorithm.md section 3), -1 for none.
double clearDepthOf(PairStep s) {
  switch (s) {
    case PairStep::SetZ:
    case PairStep::ContactNear:
      return 0.0;
    case PairStep::LoadAmin:
    case PairStep::ContactFar:
      return 1.0;
    default:
      return -1.0;
  }
}

void append(std::vector<Picture>& to, std::vector<Picture> pictures) {
  for (Picture& p : pictures)
    to.push_back(std::move(p));
}

// The section of one step: its explanation, and pictures of the buffers it is about or
// changed (the case map after the read-back).
Section stepSection(const StepSnapshot& snap, const raster::PixelBuffer<std::uint8_t>& prevStencil,
                    const raster::PixelBuffer<std::uint32_t>& prevDepth,
                    const core::PairResult& result, PictureWriter& pictures, int number) {
  Section s;
  s.id = std::string(core::toString(snap.step));
  s.step = s.id;
  s.title = stepTitle(snap.step);
  s.text = originText(snap.step) + stepText(snap.step);
  if (snap.state && snap.step != PairStep::ReadStencil)
    s.text += stateText(*snap.state, clearDepthOf(snap.step));
  if (snap.step == PairStep::ReadStencil) {
    s.text += caseTableHtml(result);
    append(s.pictures, pictures.cases(number));
  } else {
    if (stepWritesDepth(snap.step) || snap.depth != prevDepth)
      append(s.pictures, pictures.depth(snap, number));
    if (stepWritesStencil(snap.step) || snap.stencil != prevStencil) {
      append(s.pictures, pictures.stencil(snap, number));
      append(s.pictures, pictures.changes(snap, prevStencil, number));
    }
  }
  return s;
}

}  // namespace

std::vector<Section> buildSections(const core::PairResult& result,
                                   const std::vector<StepSnapshot>& snapshots, core::MorMode mor,
                                   bool boxTest, PictureWriter& pictures,
                                   const std::string& descentHtml) {
  std::vector<Section> sections;
  const auto next = [&sections] { return static_cast<int>(sections.size()) + 1; };
  const raster::PixelRect frame = pictures.frame();
  Section first;
  first.id = "silhouettes";
  first.title = kSilhouettesTitle;
  first.text = silhouettesText(result, mor, boxTest, frame);
  first.pictures = pictures.silhouettes(next());
  sections.push_back(std::move(first));
  if (!descentHtml.empty()) {
    Section descent;
    descent.id = "descent";
    descent.title = "The box descent: how recode run came to this pair";
    descent.text = descentHtml;
    sections.push_back(std::move(descent));
  }
  const raster::PixelBuffer<std::uint8_t> noStencil(frame, std::uint8_t{0});
  const raster::PixelBuffer<std::uint32_t> farDepth(frame, raster::kDepthMax);
  const raster::PixelBuffer<std::uint8_t>* prevStencil = &noStencil;
  const raster::PixelBuffer<std::uint32_t>* prevDepth = &farDepth;
  for (const StepSnapshot& snap : snapshots) {
    sections.push_back(stepSection(snap, *prevStencil, *prevDepth, result, pictures, next()));
    prevStencil = &snap.stencil;
    prevDepth = &snap.depth;
  }
  if (result.collide) {
    Section contact;
    contact.id = "contact";
    contact.title = kContactTitle;
    contact.text = contactText(result.contact);
    contact.pictures = pictures.contact(next());
    sections.push_back(std::move(contact));
  }
  return sections;
}

ExplainedRun explainRun(const PairSetup& setup, const core::PairResult& result,
                        const std::vector<StepSnapshot>& snapshots, core::MorMode mor, bool boxTest,
                        const std::filesystem::path& dir, std::vector<KeptPicture>* kept,
                        const std::string& descentHtml) {
  const core::FrameSpec& f = setup.frame;
  const auto range =
      core::pairDepthRange(f.axis, core::boundingBox(setup.a), core::boundingBox(setup.b));
  const raster::PixelBuffer<std::uint8_t> coverage = blockCoverage(setup, range[0], range[1]);
  PictureWriter pictures(dir, setup, result, coverage, kept);
  ExplainedRun run;
  run.sections = buildSections(result, snapshots, mor, boxTest, pictures, descentHtml);
  run.scale = pictures.scale();
  run.view = pictures.view();
  const FaceDepths facesA = faceDepths(setup, setup.a, range[0], range[1]);
  const FaceDepths facesB = faceDepths(setup, setup.b, range[0], range[1]);
  const RayInputs rays{result, snapshots, coverage, facesA, facesB, range[0], range[1]};
  const raster::PixelRect frameRect{0, 0, f.width, f.height};
  run.rays = rayArrays(rays, frameRect, rayCrop(rays, frameRect));
  return run;
}

}  // namespace recode::explain
