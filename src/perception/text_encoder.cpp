#include "ussnav/perception/text_encoder.hpp"

#include <cmath>

#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/random.hpp"
#include "ussnav/perception/wordnet.hpp"

namespace ussnav {

namespace {

uint64_t fnv1a(const std::string& s) {
  uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

Embedding normalised(Embedding v) {
  const float n = v.norm();
  if (n > 0) v /= n;
  return v;
}

}  // namespace

double cosineSimilarity(const Embedding& a, const Embedding& b) {
  if (a.size() != b.size() || a.size() == 0) return 0.0;
  const double na = a.norm(), nb = b.norm();
  if (na <= 0 || nb <= 0) return 0.0;
  return double(a.dot(b)) / (na * nb);
}

Embedding hashedDirection(const std::string& key, int dim) {
  Rng rng(fnv1a(key));
  Embedding v(dim);
  for (int i = 0; i < dim; ++i) v[i] = float(rng.uniform(-1.0, 1.0));
  return normalised(std::move(v));
}

Embedding ngramEmbedding(const std::string& label, int dim) {
  Embedding v = Embedding::Zero(dim);
  const auto tokens = wordnet::labelTokens(label);
  for (const auto& t : tokens) {
    const std::string padded = "#" + t + "#";
    if (padded.size() < 3) {
      v += hashedDirection("ng:" + padded, dim);
      continue;
    }
    for (size_t i = 0; i + 3 <= padded.size(); ++i) v += hashedDirection("ng:" + padded.substr(i, 3), dim);
  }
  // No letters or digits at all: still a unit vector, one per distinct string.
  if (tokens.empty()) v = hashedDirection("raw:" + label, dim);
  return normalised(std::move(v));
}

NgramTextEncoder::NgramTextEncoder(int dim) : dim_(dim) {
  if (dim < 1) throw InputError("text encoder", "perception.embedding_dim", "expected a positive size");
}

Embedding NgramTextEncoder::encode(const std::string& label) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = cache_.find(label);
  if (it != cache_.end()) return it->second;
  return cache_.emplace(label, ngramEmbedding(label, dim_)).first->second;
}

WordNetTextEncoder::WordNetTextEncoder(int dim, double depth_ratio, double modifier_weight)
    : dim_(dim), depth_ratio_(depth_ratio), modifier_weight_(modifier_weight) {
  if (dim < 1) throw InputError("text encoder", "perception.embedding_dim", "expected a positive size");
}

bool WordNetTextEncoder::usingWordNet() const { return wordnet::available(); }

Embedding WordNetTextEncoder::encode(const std::string& label) const {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = cache_.find(label);
    if (it != cache_.end()) return it->second;
  }
  // Computed outside our lock (WordNet has its own); two threads may race to the same value.
  Embedding v = encodeUncached(label);
  std::lock_guard<std::mutex> lock(mutex_);
  return cache_.emplace(label, std::move(v)).first->second;
}

Embedding WordNetTextEncoder::encodeUncached(const std::string& label) const {
  // Each ancestor a (itself included) adds w(a) * dir(a) with w^2 = ratio^depth(a): shared
  // ancestors contribute the same terms to both labels, so the cosine is the shared part of
  // the squared weight over the geometric mean of both totals (plus ~1/sqrt(dim) noise from
  // the random directions).
  auto synsetVector = [&](const wordnet::Sense& s) {
    Embedding v = Embedding::Zero(dim_);
    for (const auto& a : s.ancestors)
      v += float(std::pow(depth_ratio_, 0.5 * a.depth)) * hashedDirection("wn:" + std::to_string(a.offset), dim_);
    return normalised(std::move(v));
  };
  auto r = wordnet::resolveLabel(label);
  if (!r) return ngramEmbedding(label, dim_);
  Embedding v = synsetVector(r->sense);
  for (const auto& m : r->modifiers) {
    auto ms = wordnet::lookupNoun(m);
    // An animal before the head noun says whom the object is for ("dog bed", "cat tree"): not
    // the thing a person asking for a bed wants (ProcTHOR keeps DogBed apart from Bed too), so
    // it weighs as much as the head. Other modifiers only nudge ("office chair" is a chair).
    const double w = wordnet::namesAnimal(m) ? 1.0 : modifier_weight_;
    v += float(w) * (ms ? synsetVector(*ms) : ngramEmbedding(m, dim_));
  }
  return normalised(std::move(v));
}

std::unique_ptr<TextEncoder> makeTextEncoder(const std::string& name, int dim) {
  if (name == "wordnet") return std::make_unique<WordNetTextEncoder>(dim);
  if (name == "ngram") return std::make_unique<NgramTextEncoder>(dim);
  throw InputError("config", "perception.text_encoder", "'" + name + "' is not one of wordnet|ngram");
}

std::unique_ptr<TextEncoder> makeTextEncoder(const PerceptionConfig& cfg) {
  return makeTextEncoder(cfg.text_encoder, cfg.embedding_dim);
}

}  // namespace ussnav
