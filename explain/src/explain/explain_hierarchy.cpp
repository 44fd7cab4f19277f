// One block pair of a scene of object trees, and the box descent of its two objects.
#include "explain/explain_hierarchy.hpp"

#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "explain/explain_format.hpp"
#include "recode/scene/scene.hpp"
#include "recode/sim/hierarchy.hpp"
#include "recode/sim/simulation.hpp"

namespace recode::explain {

namespace {

using core::ObjectTree;

struct Block {
  int object = -1;  // index into the simulation's objects
  int node = -1;    // leaf index in that tree
};

// The leaf called `name`: its full path, else its own name when exactly one leaf has it.
Block findBlock(const std::vector<ObjectTree>& objects, const std::string& name,
                const std::string& pairSpec) {
  std::vector<Block> byName;
  std::vector<std::string> all;
  for (std::size_t o = 0; o < objects.size(); ++o)
    for (int leaf : objects[o].leaves()) {
      const std::string& path = objects[o].nodes()[static_cast<std::size_t>(leaf)].path;
      all.push_back(path);
      if (path == name)
        return {static_cast<int>(o), leaf};
      const std::size_t slash = path.rfind('/');
      if (slash != std::string::npos && path.substr(slash + 1) == name)
        byName.push_back({static_cast<int>(o), leaf});
    }
  if (byName.size() == 1)
    return byName.front();
  std::string list;
  for (std::size_t i = 0; i < all.size() && i < 12; ++i)
    list += (i ? ", " : "") + all[i];
  if (all.size() > 12)
    list += ", ...";
  throw std::invalid_argument("--pair " + pairSpec + ": " +
                              (byName.empty()
                                   ? "no block is called '" + name + "'"
                                   : "several blocks are called '" + name + "' (give the path)") +
                              "; the scene's blocks: " + list);
}

// The descent of core::descendPair, step by step, to show which node pairs were tested.
struct Tested {
  int a, b;
  bool overlap;
};
std::vector<Tested> traceDescent(const ObjectTree& a, const ObjectTree& b) {
  std::vector<Tested> trace;
  std::vector<std::pair<int, int>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const core::HierarchyNode& na = a.nodes()[static_cast<std::size_t>(i)];
    const core::HierarchyNode& nb = b.nodes()[static_cast<std::size_t>(j)];
    const bool overlap = core::nodeBoxesOverlap(na, nb);
    trace.push_back({i, j, overlap});
    if (!overlap || (na.isLeaf() && nb.isLeaf()))
      continue;
    const bool splitA =
        !na.isLeaf() && (nb.isLeaf() || na.worldAabb.diagonal() >= nb.worldAabb.diagonal());
    if (splitA)
      for (int c : na.children)
        stack.emplace_back(c, j);
    else
      for (int c : nb.children)
        stack.emplace_back(i, c);
  }
  return trace;
}

std::string descentHtml(const ObjectTree& ta, const ObjectTree& tb, const Block& a, const Block& b,
                        int frame) {
  std::ostringstream h;
  const auto pathOf = [](const ObjectTree& t, int node) {
    return escapeHtml(t.nodes()[static_cast<std::size_t>(node)].path);
  };
  if (a.object == b.object) {
    h << "<p>Both blocks belong to the object <b>" << escapeHtml(ta.name())
      << "</b>: <code>recode run</code> never tests the blocks of one object against each "
         "other, so there is no box descent; the passes below run on the pair as asked.</p>";
    return h.str();
  }
  std::vector<core::LeafPair> reached;
  const long long tests = core::descendPair(ta, tb, reached);
  const std::vector<Tested> trace = traceDescent(ta, tb);
  bool chosenReached = false;
  for (const core::LeafPair& p : reached)
    chosenReached = chosenReached || (p.leafA == a.node && p.leafB == b.node);
  h << "<p>At frame " << frame << " the objects <b>" << escapeHtml(ta.name()) << "</b> and <b>"
    << escapeHtml(tb.name())
    << "</b> are trees of blocks. Before any pixel is drawn, <code>recode run</code> descends "
       "both trees from their roots: a pair of nodes whose boxes (world AABB and OBB) overlap "
       "is split into the children of the larger one, a pair whose boxes are apart is dropped "
       "with everything below it, and a pair of blocks whose boxes overlap goes to the passes. "
    << tests << " node pairs were tested; " << reached.size()
    << " block pairs reached the passes. The pair explained here "
    << (chosenReached ? "is one of them."
                      : "is <b>not</b> one of them: its boxes (or an ancestor "
                        "pair's) are apart, so recode run never draws it; "
                        "the passes below run it anyway.")
    << "</p>";
  if (static_cast<long long>(trace.size()) != tests)
    h << "<p><b>The trace below has " << trace.size() << " tests, the descent counted " << tests
      << ".</b></p>";
  h << "<table><tr><th>#</th><th>node of " << escapeHtml(ta.name()) << "</th><th>node of "
    << escapeHtml(tb.name()) << "</th><th>boxes</th><th>then</th></tr>";
  int n = 0;
  for (const Tested& t : trace) {
    const bool leaves = ta.nodes()[static_cast<std::size_t>(t.a)].isLeaf() &&
                        tb.nodes()[static_cast<std::size_t>(t.b)].isLeaf();
    const bool chosen = t.a == a.node && t.b == b.node;
    h << "<tr" << (chosen ? " class=\"hit\"" : "") << "><td>" << ++n << "</td><td>"
      << pathOf(ta, t.a) << "</td><td>" << pathOf(tb, t.b) << "</td><td>"
      << (t.overlap ? "overlap" : "apart") << "</td><td>"
      << (!t.overlap ? "dropped"
          : leaves   ? "to the passes"
                     : "split")
      << (chosen ? " (this pair)" : "") << "</td></tr>";
  }
  h << "</table>";
  return h.str();
}

}  // namespace

HierarchyPair hierarchyPair(const std::string& scenePath, int frame, const std::string& pairSpec,
                            const core::FrameOverrides& overrides) {
  if (frame < 0 || frame >= core::kMaxFrames)
    throw std::invalid_argument("--frame " + std::to_string(frame) + ": expected 0.." +
                                std::to_string(core::kMaxFrames - 1));
  const std::size_t colon = pairSpec.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == pairSpec.size())
    throw std::invalid_argument("--pair " + pairSpec + ": expected NAME_A:NAME_B");
  const core::Scene scene = core::loadScene(scenePath);
  core::RunOptions options;
  options.overrides = overrides;
  options.threads = 1;
  core::Simulation sim(scene, options);
  (void)sim.runFrame(frame);  // poses every node at the frame, as recode run does
  sim.updateAllBounds();      // and the boxes of blocks near no other, which it leaves
  const std::vector<ObjectTree>& objects = sim.objects();
  const Block a = findBlock(objects, pairSpec.substr(0, colon), pairSpec);
  const Block b = findBlock(objects, pairSpec.substr(colon + 1), pairSpec);
  if (a.object == b.object && a.node == b.node)
    throw std::invalid_argument("--pair " + pairSpec + ": names the same block twice");
  const ObjectTree& ta = objects[static_cast<std::size_t>(a.object)];
  const ObjectTree& tb = objects[static_cast<std::size_t>(b.object)];
  HierarchyPair out;
  PairSetup& s = out.setup;
  s.source = scenePath + " at frame " + std::to_string(frame);
  s.nameA = ta.nodes()[static_cast<std::size_t>(a.node)].path;
  s.nameB = tb.nodes()[static_cast<std::size_t>(b.node)].path;
  s.a = ta.worldMesh(a.node);
  s.b = tb.worldMesh(b.node);
  s.frame = sim.pairFrame(ta.nodes()[static_cast<std::size_t>(a.node)].worldAabb,
                          tb.nodes()[static_cast<std::size_t>(b.node)].worldAabb);
  out.descentHtml = descentHtml(ta, tb, a, b, frame);
  return out;
}

}  // namespace recode::explain
