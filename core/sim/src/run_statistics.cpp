// Table 2 statistics: totals, means and population standard deviations of the frame times.
#include "recode/sim/run_statistics.hpp"

#include <cmath>
#include <span>

namespace recode::core {

// Two passes, for accuracy.
Moments moments(std::span<const double> values) {
  Moments m;
  if (values.empty())
    return m;
  for (double v : values)
    m.total += v;
  m.mean = m.total / static_cast<double>(values.size());
  double squares = 0.0;
  for (double v : values)
    squares += (v - m.mean) * (v - m.mean);
  m.sd = std::sqrt(squares / static_cast<double>(values.size()));
  return m;
}

void RunStatisticsAccumulator::add(const FrameReport& frame) {
  frameUs_.push_back(frame.frameUs);
  collisionUs_.push_back(frame.collisionUs);
  counts_.objectPairs += frame.objectPairs;
  counts_.boxTests += frame.boxTests;
  counts_.pairTests += frame.pairTests;
  counts_.pairTestsSkipped += frame.pairTestsSkipped;
  counts_.stencilPixelsRead += frame.stencilPixelsRead;
  counts_.depthPixelsRead += frame.depthPixelsRead;
  counts_.contacts += static_cast<long long>(frame.contacts.size());
  if (!frame.contacts.empty()) {
    ++counts_.framesWithContact;
    if (counts_.firstContactFrame < 0)
      counts_.firstContactFrame = frame.frame;
  }
}

RunStatistics RunStatisticsAccumulator::result(long long triangles) const {
  RunStatistics s = counts_;
  s.triangles = triangles;
  s.frames = static_cast<int>(frameUs_.size());
  const Moments f = moments(frameUs_), c = moments(collisionUs_);
  s.totalFrameS = f.total * 1e-6;
  s.meanFrameMs = f.mean * 1e-3;
  s.sdFrameMs = f.sd * 1e-3;
  s.totalCollisionS = c.total * 1e-6;
  s.meanCollisionMs = c.mean * 1e-3;
  s.sdCollisionMs = c.sd * 1e-3;
  return s;
}

}  // namespace recode::core
