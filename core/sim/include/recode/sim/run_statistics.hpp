#pragma once
// The statistics of a run, after the paper's Table 2 (Baciu, Wong and Sun 1999):
//   NTR  triangles in the scene          TNF  frames run
//   TTF  total frame time, s             TTC  total collision time, s
//   ATF  mean frame time, ms             ATC  mean collision time, ms
//   DTF  standard deviation of frame     DTC  standard deviation of collision time, ms
//        time, ms
// Here nothing is displayed: a frame's time is posing the nodes (motion, joints) plus
// collision detection, and collision time is collision detection alone (boxes, broad phase,
// descent, pair tests). Standard deviations are of the population (divided by TNF). The
// counters of the paper's Table 1 come with them: box tests, pair tests, pixels read, contacts.

#include <span>
#include <vector>

#include "recode/sim/simulation.hpp"

namespace recode::core {

struct RunStatistics {
  long long triangles = 0;                                                   // NTR
  int frames = 0;                                                            // TNF
  double totalFrameS = 0.0, meanFrameMs = 0.0, sdFrameMs = 0.0;              // TTF ATF DTF
  double totalCollisionS = 0.0, meanCollisionMs = 0.0, sdCollisionMs = 0.0;  // TTC ATC DTC
  long long objectPairs = 0;       // object pairs from the broad phase, summed over frames
  long long boxTests = 0;          // node-pair box tests in the descent
  long long pairTests = 0;         // leaf pairs given to the pair algorithm
  long long pairTestsSkipped = 0;  // of those, pairs the skip-apart mode proved apart undrawn
  long long stencilPixelsRead = 0;
  long long depthPixelsRead = 0;
  long long contacts = 0;      // interfering leaf pairs, summed over frames
  int firstContactFrame = -1;  // -1: none
  int framesWithContact = 0;
};

// Total, mean and population standard deviation of a series (frame times; `recode bench`'s
// collision times), in the series' own unit.
struct Moments {
  double total = 0.0, mean = 0.0, sd = 0.0;
};
[[nodiscard]] Moments moments(std::span<const double> values);

class RunStatisticsAccumulator {
 public:
  void add(const FrameReport& frame);
  // The statistics of the frames added so far, for a scene of `triangles` triangles.
  [[nodiscard]] RunStatistics result(long long triangles) const;

 private:
  std::vector<double> frameUs_;
  std::vector<double> collisionUs_;
  RunStatistics counts_;
};

}  // namespace recode::core
