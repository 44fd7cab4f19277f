// collide(): the descent of two block trees, then the pair algorithm per block pair, merged into
// one result (block_pairs.hpp).
#include <chrono>
#include <vector>

#include "block_pairs.hpp"
#include "recode/api/collision.hpp"

namespace recode {

bool collide(const CollisionObject& a, const CollisionObject& b, const CollisionRequest& request,
             CollisionResult& result, DevicePool& devices) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  detail::BlockPairPlan plan;
  const std::size_t index = plan.add(a, b, request, result);
  double setupUs = 0.0;
  std::vector<detail::BlockPairAnswer> answers =
      plan.decide(request.mode, devices, request.threads, &setupUs);
  plan.merge(index, answers, result);
  result.deviceSetupUs = setupUs;
  result.collisionUs = std::chrono::duration<double, std::micro>(Clock::now() - start).count() -
                       result.deviceSetupUs;
  return result.collide;
}

bool collide(const CollisionObject& a, const CollisionObject& b, const CollisionRequest& request,
             CollisionResult& result) {
  // One pool per thread: calls from one thread reuse its CPU devices, threads share none.
  thread_local DevicePool cpuDevices;
  return collide(a, b, request, result, cpuDevices);
}

}  // namespace recode
