#include <gtest/gtest.h>

#include <map>

#include "ussnav/core/random.hpp"
#include "ussnav/objects/cloud.hpp"
#include "ussnav/objects/object_layer.hpp"
#include "ussnav/perception/wordnet.hpp"

using namespace ussnav;

namespace {

// Surface samples of an axis-aligned box [lo, hi] at `step`, with optional Gaussian noise.
std::vector<Vec3f> boxSurface(const Vec3& lo, const Vec3& hi, double step = 0.02, double noise = 0.0,
                              uint64_t seed = 1) {
  Rng rng(seed);
  std::vector<Vec3f> out;
  const Vec3 n = ((hi - lo) / step).array().ceil();
  for (int i = 0; i <= n.x(); ++i)
    for (int j = 0; j <= n.y(); ++j)
      for (int k = 0; k <= n.z(); ++k) {
        const bool face = i == 0 || j == 0 || k == 0 || i == int(n.x()) || j == int(n.y()) || k == int(n.z());
        if (!face) continue;
        Vec3 p = lo + Vec3(i, j, k).cwiseProduct(hi - lo).cwiseQuotient(n);
        if (noise > 0) p += Vec3(rng.normal(0, noise), rng.normal(0, noise), rng.normal(0, noise));
        out.push_back(p.cast<float>());
      }
  return out;
}
// Only the points with x <= x_max (a view of one end of the object).
std::vector<Vec3f> cutX(const std::vector<Vec3f>& pts, double x_max) {
  std::vector<Vec3f> out;
  for (const auto& p : pts)
    if (p.x() <= x_max) out.push_back(p);
  return out;
}

std::vector<Vec3f> chairAt(double x, double y, uint64_t seed = 1) {
  return boxSurface(Vec3(x - 0.25, y - 0.25, 0), Vec3(x + 0.25, y + 0.25, 0.9), 0.02, 0.005, seed);
}

ObjectLayer makeLayer(ObjectsConfig cfg = {}) {
  return ObjectLayer(cfg, std::make_shared<WordNetTextEncoder>());
}

}  // namespace

TEST(ObjectLayer, SameObjectSeenTwiceMergesSemantically) {
  ObjectLayer layer = makeLayer();
  const Association first = layer.integrateCloud(chairAt(1, 1, 1), "chair", 0.9, 4, 2, 0.0);
  EXPECT_EQ(first.kind, MatchKind::kNone);
  EXPECT_EQ(first.object_id, 1);
  EXPECT_FALSE(layer.objects()[0].confirmed);
  const Association second = layer.integrateCloud(chairAt(1.02, 1, 2), "chair", 0.9, 5, 3, 1.0);
  EXPECT_EQ(second.kind, MatchKind::kSemantic);
  EXPECT_EQ(second.object_id, 1);
  EXPECT_GT(second.overlap_new_old, 0.9);
  EXPECT_NEAR(second.cosine, 1.0, 1e-6);
  ASSERT_EQ(layer.size(), 1u);
  const MappedObject& o = layer.objects()[0];
  EXPECT_EQ(o.n_observations, 2);
  EXPECT_TRUE(o.confirmed);
  EXPECT_EQ(o.label, "chair");
  EXPECT_NEAR((o.centroid - Vec3(1.01, 1, 0.45)).norm(), 0.0, 0.03);
  EXPECT_NEAR(o.box.size().x(), 0.52, 0.03);
  EXPECT_DOUBLE_EQ(o.first_seen, 0.0);
  EXPECT_DOUBLE_EQ(o.last_seen, 1.0);
  EXPECT_EQ(o.node_id, 4);  // anchored where first seen
  EXPECT_EQ(o.region_id, 2);
}

TEST(ObjectLayer, SimilarLabelMergesSemantically) {
  ObjectLayer layer = makeLayer();
  layer.integrateCloud(chairAt(1, 1), "chair", 0.9, 0, 0, 0.0);
  // A partial view (a third of the chair) called "armchair": cosine > 0.75, overlap > 0.1.
  const Association a = layer.integrateCloud(cutX(chairAt(1, 1, 2), 0.9), "armchair", 0.9, 0, 0, 1.0);
  EXPECT_EQ(a.kind, MatchKind::kSemantic);
  EXPECT_GT(a.cosine, 0.75);
  EXPECT_EQ(layer.size(), 1u);
  EXPECT_EQ(layer.objects()[0].votes.size(), 2u);
}

TEST(ObjectLayer, TwoChairsSideBySideStayTwo) {
  ObjectLayer layer = makeLayer();
  // 0.7 m apart: 0.2 m gap between the 0.5 m chairs, twice tau.
  for (int round = 0; round < 3; ++round) {
    layer.integrateCloud(chairAt(1.0, 1, 10 + round), "chair", 0.9, 0, 0, round);
    const Association a = layer.integrateCloud(chairAt(1.7, 1, 20 + round), "chair", 0.9, 0, 0, round);
    EXPECT_EQ(a.candidates, round == 0 ? 1 : 2);  // the other chair is a candidate, never a match
  }
  ASSERT_EQ(layer.size(), 2u);
  EXPECT_EQ(layer.absorbedCount(), 0);
  EXPECT_EQ(layer.objects()[0].n_observations, 3);
  EXPECT_EQ(layer.objects()[1].n_observations, 3);
  EXPECT_NEAR(layer.objects()[0].centroid.x(), 1.0, 0.02);
  EXPECT_NEAR(layer.objects()[1].centroid.x(), 1.7, 0.02);
}

TEST(ObjectLayer, MislabelledReobservationMergesGeometrically) {
  ObjectLayer layer = makeLayer();
  layer.integrateCloud(chairAt(2, 3), "chair", 0.9, 0, 0, 0.0);
  const Association a = layer.integrateCloud(chairAt(2, 3, 7), "bed", 0.9, 0, 0, 1.0);
  EXPECT_EQ(a.kind, MatchKind::kGeometric);
  EXPECT_LT(a.cosine, 0.75);
  EXPECT_GT(a.overlap_new_old, 0.5);
  EXPECT_GT(a.overlap_old_new, 0.5);
  ASSERT_EQ(layer.size(), 1u);
  const MappedObject& o = layer.objects()[0];
  EXPECT_EQ(o.label, "chair");  // tie: the first label stays
  EXPECT_EQ(o.votes.size(), 2u);
  layer.integrateCloud(chairAt(2, 3, 8), "bed", 0.9, 0, 0, 2.0);
  EXPECT_EQ(layer.objects()[0].label, "bed");  // majority now
  EXPECT_EQ(layer.objects()[0].n_observations, 3);
}

TEST(ObjectLayer, PartialViewWithOtherLabelIsANewObject) {
  ObjectLayer layer = makeLayer();
  const auto sofa = boxSurface(Vec3(0, 0, 0), Vec3(2.0, 0.9, 0.8));
  layer.integrateCloud(sofa, "sofa", 0.9, 0, 0, 0.0);
  // A cushion-sized piece of the sofa's end labelled "plant": Omega(new, old) = 1 but
  // Omega(old, new) is small, so neither rule applies.
  const Association a = layer.integrateCloud(cutX(sofa, 0.3), "plant", 0.9, 0, 0, 1.0);
  EXPECT_EQ(a.kind, MatchKind::kNone);
  EXPECT_EQ(layer.size(), 2u);
  // The same piece labelled "couch" (a synonym) is a semantic match.
  EXPECT_EQ(layer.integrateCloud(cutX(sofa, 0.3), "couch", 0.9, 0, 0, 2.0).kind, MatchKind::kSemantic);
}

TEST(ObjectLayer, CandidatesAreObjectsWithinTheAssociationRadius) {
  ObjectLayer layer = makeLayer();
  layer.integrateCloud(chairAt(0, 0), "chair", 0.9, 0, 0, 0.0);
  EXPECT_EQ(layer.integrateCloud(chairAt(3, 0), "chair", 0.9, 0, 0, 1.0).candidates, 0);
  EXPECT_EQ(layer.size(), 2u);
  // A 6 m bench: a view of its far end has its centroid 2.8 m from the bench's centroid but
  // inside its box, so the bench is a candidate and the view merges.
  const auto bench = boxSurface(Vec3(10, 0, 0), Vec3(16, 0.5, 0.5));
  layer.integrateCloud(bench, "bench", 0.9, 0, 0, 2.0);
  std::vector<Vec3f> far_end;
  for (const auto& p : bench)
    if (p.x() >= 15.5) far_end.push_back(p);
  const Association end = layer.integrateCloud(far_end, "bench", 0.9, 0, 0, 3.0);
  EXPECT_EQ(end.candidates, 1);
  EXPECT_EQ(end.kind, MatchKind::kSemantic);
  EXPECT_EQ(layer.size(), 3u);
}

// The faces of box [lo, hi] a camera sees from the (-x, -y) corner (front y = lo, left x = lo)
// or, with `far`, from the opposite corner (back and right).
std::vector<Vec3f> cornerView(const Vec3& lo, const Vec3& hi, bool far, uint64_t seed) {
  std::vector<Vec3f> out;
  for (const auto& p : boxSurface(lo, hi, 0.02, 0.005, seed)) {
    const bool near_faces = p.y() <= lo.y() + 0.01 || p.x() <= lo.x() + 0.01;
    const bool far_faces = p.y() >= hi.y() - 0.01 || p.x() >= hi.x() - 0.01;
    if (far ? far_faces && !near_faces : near_faces && !far_faces) out.push_back(p);
  }
  return out;
}

TEST(ObjectLayer, BoxOverlapIsIntersectionOverTheSmallerGrownBox) {
  const Aabb a = Aabb::of(Vec3(0, 0, 0), Vec3(1, 1, 1)), b = Aabb::of(Vec3(0.5, 0, 0), Vec3(1.5, 1, 1));
  EXPECT_NEAR(ObjectLayer::boxOverlap(a, b, 0.0), 0.5, 1e-12);
  EXPECT_NEAR(ObjectLayer::boxOverlap(a, b, 0.05), 0.6 * 1.1 * 1.1 / (1.1 * 1.1 * 1.1), 1e-12);
  const Aabb small = Aabb::of(Vec3(0.2, 0.2, 0.2), Vec3(0.4, 0.4, 0.4));  // inside a: all of the smaller box
  EXPECT_NEAR(ObjectLayer::boxOverlap(a, small, 0.0), 1.0, 1e-12);
  // A flat box (a picture) still has volume once grown.
  const Aabb flat = Aabb::of(Vec3(0, 0, 0), Vec3(1, 0, 1)), flat2 = Aabb::of(Vec3(0.5, 0, 0), Vec3(1.5, 0, 1));
  EXPECT_EQ(ObjectLayer::boxOverlap(flat, flat2, 0.0), 0.0);
  EXPECT_NEAR(ObjectLayer::boxOverlap(flat, flat2, 0.05), 0.6 * 0.1 * 1.1 / (1.1 * 0.1 * 1.1), 1e-12);
  EXPECT_EQ(ObjectLayer::boxOverlap(a, Aabb::of(Vec3(2, 0, 0), Vec3(3, 1, 1)), 0.05), 0.0);
  EXPECT_EQ(ObjectLayer::boxOverlap(a, Aabb(), 0.05), 0.0);
}

TEST(ObjectLayer, ObjectSeenFromOppositeCornersIsMergedAsADuplicate) {
  // A 2.0 x 0.9 x 0.8 sofa seen from one corner, then from the opposite one: the two views share
  // only the edges, so Omega(new, old) < semantic_overlap and association makes a second object;
  // their boxes coincide, so the duplicate step merges it into the first.
  const Vec3 lo(1, 1, 0), hi(3, 1.9, 0.8);
  ObjectsConfig off;
  off.merge_box_overlap = 0.0;
  for (const bool merge : {false, true}) {
    ObjectLayer layer = makeLayer(merge ? ObjectsConfig{} : off);
    layer.integrateCloud(cornerView(lo, hi, false, 1), "sofa", 0.9, 4, 1, 0.0);
    const Association a = layer.integrateCloud(cornerView(lo, hi, true, 2), "couch", 0.9, 9, 2, 1.0);
    EXPECT_EQ(a.kind, MatchKind::kNone);  // the views alone are not a match
    if (!merge) {
      EXPECT_EQ(layer.size(), 2u);
      EXPECT_EQ(a.absorbed, 0);
      continue;
    }
    EXPECT_EQ(a.absorbed, 1);
    EXPECT_EQ(a.object_id, 1);  // the older object survives
    ASSERT_EQ(layer.size(), 1u);
    EXPECT_EQ(layer.absorbedCount(), 1);
    const MappedObject& o = layer.objects()[0];
    EXPECT_EQ(o.n_observations, 2);
    EXPECT_TRUE(o.confirmed);
    EXPECT_EQ(o.node_id, 4);
    EXPECT_EQ(o.first_seen, 0.0);
    EXPECT_EQ(o.last_seen, 1.0);
    EXPECT_EQ(o.votes.size(), 2u);
    EXPECT_NEAR(o.centroid.x(), 2.0, 0.05);
    EXPECT_NEAR(o.centroid.y(), 1.45, 0.05);
    EXPECT_NEAR(o.box.size().x(), 2.0, 0.05);
    EXPECT_NEAR(o.box.size().y(), 0.9, 0.05);
    // The absorbed id leads to the survivor; a third view now merges directly.
    ASSERT_NE(layer.find(2), nullptr);
    EXPECT_EQ(layer.find(2)->id, 1);
    EXPECT_EQ(layer.find(3), nullptr);
    EXPECT_EQ(layer.integrateCloud(cornerView(lo, hi, true, 3), "sofa", 0.9, 0, 0, 2.0).kind, MatchKind::kSemantic);
    EXPECT_EQ(layer.size(), 1u);
  }
}

TEST(ObjectLayer, OverlappingObjectsWithDifferentLabelsAreNotMerged) {
  // A chair pushed under a table: its box lies inside the table's box, but the labels disagree.
  ObjectLayer layer = makeLayer();
  layer.integrateCloud(boxSurface(Vec3(0, 0, 0), Vec3(1.4, 0.9, 0.75)), "table", 0.9, 0, 0, 0.0);
  layer.integrateCloud(boxSurface(Vec3(0.5, 0.2, 0.1), Vec3(0.9, 0.6, 0.55)), "chair", 0.9, 0, 0, 1.0);
  EXPECT_EQ(layer.size(), 2u);
  EXPECT_EQ(layer.absorbedCount(), 0);
  EXPECT_GT(ObjectLayer::boxOverlap(layer.objects()[0].box, layer.objects()[1].box, 0.05), 0.9);
}

TEST(ObjectLayer, TooFewPointsAreRejected) {
  ObjectsConfig cfg;
  cfg.min_points = 10;
  ObjectLayer layer = makeLayer(cfg);
  std::vector<Vec3f> tiny;
  for (int i = 0; i < 9; ++i) tiny.emplace_back(0.06f * i, 0, 0);  // 9 voxels
  const Association a = layer.integrateCloud(tiny, "cup", 0.9, 0, 0, 0.0);
  EXPECT_TRUE(a.rejected);
  EXPECT_EQ(layer.size(), 0u);
  // 100 points in one voxel are still one point.
  EXPECT_TRUE(layer.integrateCloud(std::vector<Vec3f>(100, Vec3f(0.01f, 0.01f, 0.01f)), "cup", 0.9, 0, 0, 0).rejected);
}

TEST(ObjectLayer, RegionsFollowTheirNodes) {
  ObjectLayer layer = makeLayer();
  layer.integrateCloud(chairAt(0, 0), "chair", 0.9, 7, 3, 0.0);
  layer.integrateCloud(chairAt(5, 0), "chair", 0.9, 8, 3, 0.0);
  layer.integrateCloud(chairAt(0, 0, 3), "chair", 0.9, 9, 4, 1.0);  // merge: anchor unchanged
  EXPECT_EQ(layer.find(1)->node_id, 7);
  EXPECT_EQ(layer.find(1)->region_id, 3);
  layer.setRegionOf([](int node) { return node == 7 ? 11 : 12; });
  EXPECT_EQ(layer.find(1)->region_id, 11);
  EXPECT_EQ(layer.find(2)->region_id, 12);
  EXPECT_EQ(layer.find(3), nullptr);
  EXPECT_EQ(layer.find(0), nullptr);
  EXPECT_EQ(layer.find(2)->id, 2);
}

TEST(ObjectLayer, LargeCloudsAreCoarsened) {
  ObjectsConfig cfg;
  cfg.max_points_per_object = 300;
  ObjectLayer layer = makeLayer(cfg);
  layer.integrateCloud(boxSurface(Vec3(0, 0, 0), Vec3(2, 1, 1)), "sofa", 0.9, 0, 0, 0.0);
  const MappedObject& o = layer.objects()[0];
  EXPECT_LE(o.cloud.size(), 300u);
  EXPECT_GT(o.voxel_size, cfg.voxel_size);
  EXPECT_NEAR(o.box.size().x(), 2.0, 2 * o.voxel_size);
  // Still recognised when seen again.
  EXPECT_EQ(layer.integrateCloud(boxSurface(Vec3(0, 0, 0), Vec3(2, 1, 1), 0.02, 0.005, 9), "sofa", 0.9, 0, 0, 1.0).kind,
            MatchKind::kSemantic);
}

TEST(ObjectLayer, IntegrateBackProjectsDetections) {
  // A camera at the origin looking along +x; a 20 x 20 pixel mask on a wall 2 m ahead.
  DepthFrame f;
  f.K = Intrinsics::fromFov(80, 60, deg2rad(87), deg2rad(58));
  f.depth.assign(80 * 60, 2.0f);
  f.T_world_camera.linear() = opticalToBody();
  Detection d;
  d.label = "picture";
  d.score = 0.8;
  for (int v = 20; v < 40; ++v)
    for (int u = 30; u < 50; ++u) d.mask.push_back(uint32_t(v * 80 + u));
  Detection small = d;
  small.mask.resize(3);
  ObjectLayer layer = makeLayer();
  IntegrateStats st = layer.integrate({d, small}, f, 1, 2, 0.5);
  EXPECT_EQ(st.created, 1);
  EXPECT_EQ(st.rejected, 1);
  ASSERT_EQ(layer.size(), 1u);
  const MappedObject& o = layer.objects()[0];
  EXPECT_NEAR(o.centroid.x(), 2.0, 1e-3);  // on the wall
  EXPECT_NEAR(o.centroid.y(), 0.0, 0.05);  // centred in the image
  EXPECT_NEAR(o.centroid.z(), 0.0, 0.05);
  // The mask spans 20 px at fx = 40 / tan(43.5 deg): about 0.84 m at 2 m.
  EXPECT_NEAR(o.box.size().y(), 20 * 2.0 / f.K.fx, 0.06);
  st = layer.integrate({d}, f, 1, 2, 1.0);
  EXPECT_EQ(st.merged_semantic, 1);
  EXPECT_EQ(layer.objects()[0].n_observations, 2);
  EXPECT_EQ(layer.confirmedCount(), 1u);
}

TEST(ObjectLayer, AFewMisreadFramesAreOutvotedByTheObjectTheyRead) {
  ObjectLayer layer = makeLayer();
  const auto bed = boxSurface(Vec3(0, 0, 0), Vec3(2.0, 1.6, 0.6), 0.02, 0.005);
  for (int i = 0; i < 12; ++i) layer.integrateCloud(bed, "bed", 0.9, 0, 0, i);
  // Three frames call the bed's foot end "sofa": a separate object (see the test above).
  for (int i = 0; i < 3; ++i) layer.integrateCloud(cutX(bed, 0.6), "sofa", 0.9, 0, 0, 20 + i);
  // A pillow on the bed: its own surface, above the bed's top.
  const auto pillow = boxSurface(Vec3(1.5, 0.4, 0.62), Vec3(1.9, 1.2, 0.75), 0.02, 0.003);
  for (int i = 0; i < 3; ++i) layer.integrateCloud(pillow, "pillow", 0.9, 0, 0, 30 + i);
  // A real sofa elsewhere, seen as often as the misread one.
  const auto sofa = boxSurface(Vec3(4, 0, 0), Vec3(6, 0.9, 0.8), 0.02, 0.005);
  for (int i = 0; i < 3; ++i) layer.integrateCloud(sofa, "sofa", 0.9, 0, 0, 40 + i);
  ASSERT_EQ(layer.size(), 4u);
  auto labelled = [&](const std::string& l, double x_lo, double x_hi) -> const MappedObject& {
    for (const MappedObject& o : layer.objects())
      if (o.label == l && o.centroid.x() >= x_lo && o.centroid.x() <= x_hi) return o;
    ADD_FAILURE() << "no " << l;
    return layer.objects()[0];
  };
  const MappedObject& the_bed = labelled("bed", 0, 2);
  const MappedObject& misread = labelled("sofa", 0, 2);
  EXPECT_EQ(the_bed.n_observations, 12);
  EXPECT_EQ(misread.n_observations, 3);
  const MappedObject* by = outvotedBy(layer, misread);
  ASSERT_NE(by, nullptr);
  EXPECT_EQ(by->id, the_bed.id);
  EXPECT_EQ(outvotedBy(layer, labelled("pillow", 1.4, 2)), nullptr);  // its own surface
  EXPECT_EQ(outvotedBy(layer, labelled("sofa", 4, 6)), nullptr);      // nothing shares it
  EXPECT_EQ(outvotedBy(layer, the_bed), nullptr);                     // the majority itself
  // Five readings against twelve (under the ratio 3): the reading stands.
  for (int i = 0; i < 2; ++i) layer.integrateCloud(cutX(bed, 0.6), "sofa", 0.9, 0, 0, 50 + i);
  EXPECT_EQ(outvotedBy(layer, labelled("sofa", 0, 2)), nullptr);
}

TEST(ObjectLayer, SeenWithinNamesOnlyAGoalObjectObservedNowAndNearby) {
  ObjectLayer layer = makeLayer();
  // A toilet seen at t = 1 and 2, a sink beside it seen at t = 3, a second toilet 4 m away seen
  // at t = 3.
  const auto toilet = boxSurface(Vec3(0, 0, 0), Vec3(0.7, 0.4, 0.8), 0.02, 0.003);
  const auto sink = boxSurface(Vec3(1.2, 0, 0.6), Vec3(1.8, 0.5, 0.9), 0.02, 0.003);
  const auto far = boxSurface(Vec3(4, 0, 0), Vec3(4.7, 0.4, 0.8), 0.02, 0.003);
  layer.integrateCloud(toilet, "toilet", 0.9, 0, 0, 1.0);
  layer.integrateCloud(toilet, "toilet", 0.9, 0, 0, 2.0);
  layer.integrateCloud(sink, "sink", 0.9, 0, 0, 3.0);
  layer.integrateCloud(far, "toilet", 0.9, 0, 0, 3.0);
  ASSERT_EQ(layer.size(), 3u);
  auto isToilet = [](const std::string& l) { return l == "toilet"; };
  const Vec3 uav(0.35, -0.8, 0.5);  // 0.8 m in front of the first toilet's box
  const MappedObject* now = seenWithin(layer, isToilet, uav, 1.0, 2.0);
  ASSERT_NE(now, nullptr);
  EXPECT_NEAR(now->centroid.x(), 0.35, 0.05);
  // At t = 3 the near toilet is not in the frame (a wall between), only the sink is: no goal in view.
  EXPECT_EQ(seenWithin(layer, isToilet, uav, 1.0, 3.0), nullptr);
  // The far toilet, seen at t = 3, is beyond the radius from here, but within it from nearby.
  EXPECT_EQ(seenWithin(layer, isToilet, uav, 3.0, 3.0), nullptr);
  const MappedObject* far_seen = seenWithin(layer, isToilet, Vec3(4.35, -0.8, 0.5), 1.0, 3.0);
  ASSERT_NE(far_seen, nullptr);
  EXPECT_NEAR(far_seen->centroid.x(), 4.35, 0.05);
  // Of two in view, the nearer.
  layer.integrateCloud(toilet, "toilet", 0.9, 0, 0, 4.0);
  layer.integrateCloud(far, "toilet", 0.9, 0, 0, 4.0);
  const MappedObject* nearer = seenWithin(layer, isToilet, Vec3(1.0, -0.5, 0.5), 5.0, 4.0);
  ASSERT_NE(nearer, nullptr);
  EXPECT_NEAR(nearer->centroid.x(), 0.35, 0.05);
}
