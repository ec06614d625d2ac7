#include "ussnav/objects/object_layer.hpp"

#include <nanoflann.hpp>

#include <algorithm>

#include "ussnav/core/error.hpp"
#include "ussnav/objects/cloud.hpp"

namespace ussnav {

const char* toString(MatchKind k) {
  switch (k) {
    case MatchKind::kSemantic: return "semantic";
    case MatchKind::kGeometric: return "geometric";
    default: return "none";
  }
}

IntegrateStats& IntegrateStats::operator+=(const IntegrateStats& o) {
  created += o.created;
  merged_semantic += o.merged_semantic;
  merged_geometric += o.merged_geometric;
  rejected += o.rejected;
  absorbed += o.absorbed;
  return *this;
}

// Per-object bookkeeping the public MappedObject does not show.
struct ObjectLayer::State {
  VoxelCloud cloud;  // voxel means + neighbour index within tau: Omega(new, this)
  Embedding embedding_sum;
};

// nanoflann over the object centroids, rebuilt lazily after any change. The radius search
// uses R + the largest centroid-to-box-corner distance, then the exact box test filters.
struct ObjectLayer::CentroidIndex {
  struct Adaptor {
    const std::vector<Vec3>* pts;
    size_t kdtree_get_point_count() const { return pts->size(); }
    double kdtree_get_pt(size_t i, size_t d) const { return (*pts)[i][int(d)]; }
    template <class B> bool kdtree_get_bbox(B&) const { return false; }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Adaptor>, Adaptor, 3>;

  std::vector<Vec3> centroids;
  Adaptor adaptor{&centroids};
  std::unique_ptr<Tree> tree;
  double max_extent = 0.0;
  bool dirty = true;        // some centroid moved or an object was added since the build
  bool rows_valid = false;  // row i is still objects_[i] (false once an object was erased)

  void rebuild(const std::vector<MappedObject>& objects) {
    centroids.clear();
    max_extent = 0.0;
    for (const auto& o : objects) {
      centroids.push_back(o.centroid);
      if (!o.box.empty())
        max_extent = std::max(max_extent, (o.box.size() / 2 + (o.box.center() - o.centroid).cwiseAbs()).norm());
    }
    tree = std::make_unique<Tree>(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree->buildIndex();
    dirty = false;
    rows_valid = true;
  }
};

ObjectLayer::ObjectLayer(const ObjectsConfig& cfg, std::shared_ptr<const TextEncoder> encoder)
    : cfg_(cfg), encoder_(std::move(encoder)), index_(std::make_unique<CentroidIndex>()) {
  if (!encoder_) throw InputError("object layer", "perception.text_encoder", "a text encoder is required");
}
ObjectLayer::~ObjectLayer() = default;
ObjectLayer::ObjectLayer(ObjectLayer&&) noexcept = default;
ObjectLayer& ObjectLayer::operator=(ObjectLayer&&) noexcept = default;

const MappedObject* ObjectLayer::find(int id) const {
  for (auto r = redirect_.find(id); r != redirect_.end(); r = redirect_.find(id)) id = r->second;
  const auto it = position_.find(id);
  return it == position_.end() ? nullptr : &objects_[it->second];
}

double ObjectLayer::boxOverlap(const Aabb& a, const Aabb& b, double grow) {
  if (a.empty() || b.empty()) return 0.0;
  const Vec3 ea = (a.size().array() + 2 * grow).max(0.0), eb = (b.size().array() + 2 * grow).max(0.0);
  const Vec3 lo = a.min.cwiseMax(b.min).array() - grow, hi = a.max.cwiseMin(b.max).array() + grow;
  const Vec3 e = (hi - lo).cwiseMax(Vec3::Zero());
  const double smaller = std::min(ea.prod(), eb.prod());
  return smaller > 0 ? e.prod() / smaller : 0.0;
}

size_t ObjectLayer::confirmedCount() const {
  return size_t(std::count_if(objects_.begin(), objects_.end(), [](const MappedObject& o) { return o.confirmed; }));
}

void ObjectLayer::setRegionOf(const std::function<int(int)>& region_of) {
  for (auto& o : objects_) o.region_id = region_of(o.node_id);
}

int ObjectLayer::reanchor(const std::function<int(const MappedObject&)>& anchor_of,
                          const std::function<int(int)>& region_of) {
  int moved = 0;
  for (auto& o : objects_) {
    const int node = anchor_of(o);
    if (node < 0 || node == o.node_id) continue;
    o.node_id = node;
    o.region_id = region_of(node);
    ++moved;
  }
  return moved;
}

std::vector<int> ObjectLayer::candidatesNear(const Vec3& c) {
  std::vector<int> out;
  if (objects_.empty()) return out;
  if (index_->dirty) index_->rebuild(objects_);
  const double r = cfg_.association_radius + index_->max_extent;
  std::vector<std::pair<uint32_t, double>> hits;
  index_->tree->radiusSearch(c.data(), r * r, hits, nanoflann::SearchParams(32, 0.f, false));
  for (const auto& [i, d2] : hits) {
    const Aabb& b = objects_[i].box;
    const Vec3 gap = (b.min - c).cwiseMax(c - b.max).cwiseMax(Vec3::Zero());
    if (gap.norm() <= cfg_.association_radius) out.push_back(int(i));
  }
  std::sort(out.begin(), out.end());
  return out;
}

Association ObjectLayer::integrateCloud(const std::vector<Vec3f>& world_points, const std::string& label,
                                        double score, int anchor_node, int anchor_region, double time) {
  Association a;
  VoxelCloud fresh(cfg_.voxel_size, cfg_.tau);
  fresh.insert(world_points);
  const std::vector<Vec3f>& cloud = fresh.points();
  if (int(cloud.size()) < cfg_.min_points) {
    a.rejected = true;
    return a;
  }
  const Embedding v = encoder_->encode(label);
  Vec3 centroid = Vec3::Zero();
  for (const auto& p : cloud) centroid += p.cast<double>();
  centroid /= double(cloud.size());

  Aabb reach;  // the new cloud's box grown by tau: objects outside it cannot overlap at all
  for (const auto& p : cloud) reach.extend(p.cast<double>());
  reach.min.array() -= cfg_.tau;
  reach.max.array() += cfg_.tau;

  const std::vector<int> cands = candidatesNear(centroid);
  a.candidates = int(cands.size());
  std::vector<double> cosines(cands.size()), forward(cands.size(), 0.0);
  int best = -1;
  for (size_t k = 0; k < cands.size(); ++k) {
    const Aabb& box = objects_[cands[k]].box;
    const bool touching = (box.min.array() <= reach.max.array()).all() && (reach.min.array() <= box.max.array()).all();
    if (!touching) continue;  // overlap 0: neither rule can hold
    cosines[k] = cosineSimilarity(v, objects_[cands[k]].embedding);
    // Only the rule this candidate can still meet matters: a semantic one needs the small
    // overlap, any other the geometric one (exact above it, cut short below).
    const bool semantic = cosines[k] > cfg_.semantic_cos;
    forward[k] = geometricOverlap(cloud, state_[cands[k]].cloud,
                                  semantic ? std::min(cfg_.semantic_overlap, cfg_.geometric_overlap) : cfg_.geometric_overlap);
    if (cosines[k] > cfg_.semantic_cos && forward[k] > cfg_.semantic_overlap &&
        (best < 0 || forward[k] > forward[best] || (forward[k] == forward[best] && cosines[k] > cosines[best])))
      best = int(k);
  }
  if (best >= 0) {
    a.kind = MatchKind::kSemantic;
  } else {
    double best_score = -1;
    for (size_t k = 0; k < cands.size(); ++k) {
      if (forward[k] <= cfg_.geometric_overlap) continue;
      const double backward = geometricOverlap(objects_[cands[k]].cloud, fresh, cfg_.geometric_overlap);
      if (backward > cfg_.geometric_overlap && std::min(forward[k], backward) > best_score) {
        best_score = std::min(forward[k], backward);
        best = int(k);
        a.overlap_old_new = backward;
      }
    }
    if (best >= 0) a.kind = MatchKind::kGeometric;
  }

  size_t changed;
  if (best >= 0) {
    a.cosine = cosines[best];
    a.overlap_new_old = forward[best];
    changed = size_t(cands[best]);
    merge(changed, cloud, label, score, v, time);
  } else {
    create(cloud, label, score, v, anchor_node, anchor_region, time);
    changed = objects_.size() - 1;
  }
  changed = absorbDuplicates(changed, a.absorbed);
  a.object_id = objects_[changed].id;
  return a;
}

void ObjectLayer::create(const std::vector<Vec3f>& cloud, const std::string& label, double score,
                         const Embedding& v, int node, int region, double time) {
  MappedObject o;
  o.id = next_id_++;
  o.node_id = node;
  o.region_id = region;
  o.first_seen = time;
  o.voxel_size = cfg_.voxel_size;
  position_[o.id] = objects_.size();
  objects_.push_back(std::move(o));
  state_.push_back(State{VoxelCloud(cfg_.voxel_size, cfg_.tau), Embedding::Zero(v.size())});
  merge(objects_.size() - 1, cloud, label, score, v, time);
}

void ObjectLayer::merge(size_t index, const std::vector<Vec3f>& cloud, const std::string& label, double score,
                        const Embedding& v, double time) {
  MappedObject& o = objects_[index];
  State& s = state_[index];
  s.cloud.insert(cloud);
  // A zero score would erase the observation from the label vote and embedding; count it a little.
  const double w = std::max(score, 1e-3);
  auto vote = std::find_if(o.votes.begin(), o.votes.end(), [&](const auto& lv) { return lv.first == label; });
  if (vote == o.votes.end()) o.votes.emplace_back(label, w);
  else vote->second += w;
  s.embedding_sum += float(w) * v;
  if (s.embedding_sum.norm() == 0) o.embedding = v;
  ++o.n_observations;
  o.last_seen = time;
  refresh(index);
}

void ObjectLayer::refresh(size_t index) {
  MappedObject& o = objects_[index];
  State& s = state_[index];
  // Bounded memory per object: coarsen the voxel grid until the cloud fits.
  while (int(s.cloud.size()) > cfg_.max_points_per_object) s.cloud.coarsen();
  o.voxel_size = s.cloud.voxelSize();
  o.cloud = s.cloud.points();
  o.box = Aabb();
  Vec3 c = Vec3::Zero();
  for (const auto& p : o.cloud) {
    o.box.extend(p.cast<double>());
    c += p.cast<double>();
  }
  o.centroid = c / double(std::max<size_t>(1, o.cloud.size()));
  const auto top = std::max_element(o.votes.begin(), o.votes.end(),
                                    [](const auto& x, const auto& y) { return x.second < y.second; });
  o.label = top->first;  // first maximum: ties keep the earliest label
  const float n = s.embedding_sum.norm();
  if (n > 0) o.embedding = s.embedding_sum / n;
  o.confirmed = o.n_observations >= cfg_.min_observations_to_confirm;
  index_->dirty = true;
}

size_t ObjectLayer::absorbDuplicates(size_t index, int& absorbed) {
  if (cfg_.merge_box_overlap <= 0) return index;
  for (;;) {
    const MappedObject& o = objects_[index];
    int best = -1;
    double best_overlap = cfg_.merge_box_overlap;
    // Only the object just changed has moved (or is new) since the index was built, and it is
    // the query itself: the index still finds every other object, so no rebuild is needed
    // until an absorption erases a row. The index stays marked dirty for the next association.
    std::vector<int> near;
    if (index_->tree && index_->rows_valid && index_->dirty) {
      index_->dirty = false;
      near = candidatesNear(o.centroid);
      index_->dirty = true;
    } else {
      near = candidatesNear(o.centroid);
    }
    for (int k : near) {
      if (size_t(k) == index) continue;
      const MappedObject& other = objects_[size_t(k)];
      if (cosineSimilarity(o.embedding, other.embedding) <= cfg_.semantic_cos) continue;
      const double overlap = boxOverlap(o.box, other.box, cfg_.voxel_size);
      if (overlap > best_overlap) best_overlap = overlap, best = k;
    }
    if (best < 0) return index;
    // The older object (smaller id, created first) survives; indices shift past the erased one.
    const size_t other = size_t(best);
    const bool keep_this = objects_[index].id < objects_[other].id;
    const size_t into = keep_this ? index : other, from = keep_this ? other : index;
    absorb(into, from);
    ++absorbed;
    index = into > from ? into - 1 : into;
  }
}

void ObjectLayer::absorb(size_t into, size_t from) {
  MappedObject& o = objects_[into];
  const MappedObject& f = objects_[from];
  state_[into].cloud.insert(f.cloud);
  for (const auto& [label, w] : f.votes) {
    auto vote = std::find_if(o.votes.begin(), o.votes.end(), [&](const auto& lv) { return lv.first == label; });
    if (vote == o.votes.end()) o.votes.emplace_back(label, w);
    else vote->second += w;
  }
  state_[into].embedding_sum += state_[from].embedding_sum;
  o.n_observations += f.n_observations;
  o.first_seen = std::min(o.first_seen, f.first_seen);
  o.last_seen = std::max(o.last_seen, f.last_seen);
  refresh(into);
  redirect_[f.id] = o.id;
  position_.erase(f.id);
  objects_.erase(objects_.begin() + std::ptrdiff_t(from));
  state_.erase(state_.begin() + std::ptrdiff_t(from));
  for (size_t i = from; i < objects_.size(); ++i) position_[objects_[i].id] = i;
  index_->dirty = true;
  index_->rows_valid = false;
}

IntegrateStats ObjectLayer::integrate(const std::vector<Detection>& detections, const DepthFrame& frame,
                                      int anchor_node, int anchor_region, double time) {
  IntegrateStats st;
  for (const auto& d : detections) {
    const Association a = integrateCloud(backProject(frame, d.mask), d.label, d.score, anchor_node, anchor_region, time);
    if (a.rejected) ++st.rejected;
    else if (a.kind == MatchKind::kSemantic) ++st.merged_semantic;
    else if (a.kind == MatchKind::kGeometric) ++st.merged_geometric;
    else ++st.created;
    st.absorbed += a.absorbed;
  }
  return st;
}

const MappedObject* outvotedBy(const ObjectLayer& layer, const MappedObject& o, double shared, double ratio) {
  const double tau = layer.config().tau;
  const MappedObject* best = nullptr;
  for (const MappedObject& q : layer.objects()) {
    if (q.id == o.id || q.n_observations < ratio * o.n_observations) continue;
    if (ObjectLayer::boxOverlap(o.box, q.box, tau) <= 0.0) continue;
    if (geometricOverlap(o.cloud, q.cloud, tau) < shared) continue;
    if (!best || q.n_observations > best->n_observations) best = &q;
  }
  return best;
}

const MappedObject* seenWithin(const ObjectLayer& layer, const std::function<bool(const std::string&)>& matches,
                               const Vec3& p, double radius, double time) {
  const MappedObject* best = nullptr;
  double best_d = radius;
  for (const MappedObject& o : layer.objects()) {
    if (o.last_seen != time || o.box.empty() || !matches(o.label)) continue;
    const Vec3 d = (o.box.min - p).cwiseMax(p - o.box.max).cwiseMax(Vec3::Zero());
    if (d.norm() <= best_d) best_d = d.norm(), best = &o;
  }
  return best;
}

}  // namespace ussnav
