#pragma once
// Extended capabilities on a saved scene graph (paper Sec. VI-B-3), no exploration:
//  - pickRegionForRequest: which region serves a request ("I want to attend a meeting"): a
//    region holding an object that matches the instruction's targets scores 1 (nearest such
//    object is the goal), else the builtin chance that it holds one, with a bonus when its label
//    names the required room or the request's room hint;
//  - routeOnSceneGraph: a polyline from a point to another over the graph's nodes and edges
//    (Dijkstra on centroid distances; start and goal join their nearest nodes); between two
//    nodes whose polyhedra overlap, it passes through their overlap (portalBetween) when the
//    straight stretch between the centres passes more than 0.2 m from it: polyhedra that meet
//    through a door have centres beside it, and the straight stretch cuts the door's corner;
//  - answerQuestion: a short text answer about the graph: the area at a point ("describe the
//    current area"), where objects of a kind are ("where is the bed?"), the regions labelled
//    with a room type the question names ("what is in the kitchen?"), every object label with
//    its count ("list all objects"), or the layout.
// Only the scene graph is read, never ground truth.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ussnav/reasoning/instruction.hpp"
#include "ussnav/reasoning/region_semantics.hpp"

namespace ussnav {

class Reasoner;

// Region labels of a saved graph: those it carries, the others from `reasoner` (may be null).
std::map<int, RegionSemantics> graphSemantics(const SceneGraph& g, Reasoner* reasoner);
// Every object label in the graph (extra vocabulary for instructions).
std::vector<std::string> graphVocabulary(const SceneGraph& g);

struct RegionPick {
  int region = -1;     // -1: the graph has no region
  double score = 0.0;
  int object = -1;     // matching object, -1 none
  Vec3 goal = Vec3::Zero();  // where to fly: the object, else the region's node nearest its centroid
  std::string reason;
};
RegionPick pickRegionForRequest(const SceneGraph& g, const Instruction& ins, const std::map<int, RegionSemantics>& sem,
                                const CommonsensePriors& priors, double goal_similarity = 0.85);

std::optional<std::vector<Vec3>> routeOnSceneGraph(const SceneGraph& g, const Vec3& from, const Vec3& to);

// The mean of the points at height z, on a 0.1 m lattice, inside both nodes' hulls (when none
// is, within 0.2 m of both: polyhedra linked as overlapping may only touch): where two
// overlapping polyhedra meet. nullopt when they do not meet at that height, a hull is
// degenerate (or missing), or the hulls' common box exceeds 400 m^2 (bounded work).
std::optional<Vec3> portalBetween(const SgNode& a, const SgNode& b, double z);

std::string answerQuestion(const SceneGraph& g, const std::string& question, const std::optional<Vec3>& at,
                           const std::map<int, RegionSemantics>& sem, const CommonsensePriors& priors);

}  // namespace ussnav
