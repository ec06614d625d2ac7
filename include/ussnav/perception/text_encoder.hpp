#pragma once
// Label -> unit vector, compared by cosine similarity (paper Sec. IV-C, Eq. 2: Mobile-CLIP's
// 512-d text embedding). Backends, chosen by name (perception.text_encoder):
//  - "wordnet": built-in stand-in for Mobile-CLIP that needs no model file. A label maps to one
//    WordNet noun synset (synonyms coincide: "couch" == "sofa"); its vector is the weighted sum
//    of fixed pseudo-random directions of the synset and all its hypernyms, so the cosine of two
//    labels measures how much of their hypernym chains they share, weighted towards the deep,
//    specific end (close to Wu-Palmer but sharper: "armchair"~"chair" high, "chair"~"bed" low).
//    Words WordNet lacks fall back to character 3-grams in the same space.
//  - "ngram": character 3-grams only (no WordNet), for tests and as the fallback.
// An ONNX (Mobile-CLIP) backend comes later behind the same interface. encode() is
// thread-safe and cached per label: a hit is a hash lookup, a miss draws one random direction
// per hypernym (~15 x dim numbers, tens of microseconds) after a WordNet lookup.

#include <Eigen/Core>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace ussnav {

struct PerceptionConfig;

using Embedding = Eigen::VectorXf;

// Cosine similarity; 0 when either vector is zero or the sizes differ.
double cosineSimilarity(const Embedding& a, const Embedding& b);

class TextEncoder {
 public:
  virtual ~TextEncoder() = default;
  // A unit vector of size dim(); the same label always gives the same vector.
  virtual Embedding encode(const std::string& label) const = 0;
  virtual int dim() const = 0;
  virtual std::string name() const = 0;
  double similarity(const std::string& a, const std::string& b) const {
    return cosineSimilarity(encode(a), encode(b));
  }
};

// A fixed pseudo-random unit direction for `key`: components uniform in [-1, 1) from a seeded
// Rng (no transcendental functions, so bit-identical on every platform), normalised.
Embedding hashedDirection(const std::string& key, int dim);
// Character 3-grams of each word padded as "#word#", each a hashed direction, summed and
// normalised: "zorblax" and "zorblaxes" share 6 of their 7 and 9 grams (cosine ~0.75).
Embedding ngramEmbedding(const std::string& label, int dim);

class NgramTextEncoder : public TextEncoder {
 public:
  explicit NgramTextEncoder(int dim = 512);
  Embedding encode(const std::string& label) const override;
  int dim() const override { return dim_; }
  std::string name() const override { return "ngram"; }

 private:
  int dim_;
  mutable std::mutex mutex_;
  mutable std::unordered_map<std::string, Embedding> cache_;
};

class WordNetTextEncoder : public TextEncoder {
 public:
  // depth_ratio: squared weight ratio between a synset and its hypernym one level up (> 1
  // emphasises the specific end of the chain). modifier_weight: weight of each word before the
  // head noun when the compound is not in WordNet ("office chair" = chair + 0.3 office); a
  // modifier that names an animal weighs 1 ("dog bed" = bed + dog: not a bed to a person).
  explicit WordNetTextEncoder(int dim = 512, double depth_ratio = 1.6, double modifier_weight = 0.3);
  Embedding encode(const std::string& label) const override;
  int dim() const override { return dim_; }
  std::string name() const override { return "wordnet"; }
  // True when WordNet data was found; otherwise every label goes through ngramEmbedding().
  bool usingWordNet() const;

 private:
  Embedding encodeUncached(const std::string& label) const;

  int dim_;
  double depth_ratio_, modifier_weight_;
  mutable std::mutex mutex_;
  mutable std::unordered_map<std::string, Embedding> cache_;
};

// "wordnet" | "ngram"; anything else throws InputError naming perception.text_encoder.
std::unique_ptr<TextEncoder> makeTextEncoder(const std::string& name, int dim = 512);
std::unique_ptr<TextEncoder> makeTextEncoder(const PerceptionConfig& cfg);

}  // namespace ussnav
