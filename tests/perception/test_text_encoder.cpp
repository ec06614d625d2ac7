#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/perception/text_encoder.hpp"
#include "ussnav/perception/wordnet.hpp"

using namespace ussnav;

namespace {
double cos(const TextEncoder& e, const std::string& a, const std::string& b) { return e.similarity(a, b); }
bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}
}  // namespace

TEST(WordNet, DatabaseIsInstalled) {
  ASSERT_TRUE(wordnet::available()) << "WordNet data missing in " << wordnet::searchDir();
}

TEST(WordNet, PicksTheHouseholdSense) {
  EXPECT_NE(wordnet::glossOf("bed").find("furniture that provides a place to sleep"), std::string::npos);
  // Sense 1 of "table" is a data table, of "toilet" a room, of "plant" a factory.
  EXPECT_NE(wordnet::glossOf("table").find("furniture"), std::string::npos) << wordnet::glossOf("table");
  EXPECT_NE(wordnet::glossOf("toilet").find("plumbing fixture"), std::string::npos) << wordnet::glossOf("toilet");
  EXPECT_NE(wordnet::glossOf("plant").find("living organism"), std::string::npos) << wordnet::glossOf("plant");
  EXPECT_EQ(wordnet::glossOf("plant").front(), '(');  // "(botany) a living ..." keeps its own parenthesis
  // "Monitor" the ironclad ship is only a proper name: not chosen.
  EXPECT_EQ(wordnet::glossOf("monitor").find("vessel"), std::string::npos) << wordnet::glossOf("monitor");
  EXPECT_TRUE(wordnet::glossOf("zorblax").empty());
}

TEST(WordNet, SynonymsHypernymsAndMorphology) {
  EXPECT_TRUE(contains(wordnet::synonymsOf("couch"), "sofa"));
  const auto hyp = wordnet::hypernymsOf("armchair");
  ASSERT_FALSE(hyp.empty());
  EXPECT_EQ(hyp.front(), "chair");
  EXPECT_TRUE(contains(hyp, "furniture"));
  EXPECT_EQ(hyp.back(), "entity");
  ASSERT_TRUE(wordnet::lookupLabel("chairs"));
  EXPECT_EQ(wordnet::lookupLabel("chairs")->offset, wordnet::lookupLabel("chair")->offset);
  EXPECT_DOUBLE_EQ(*wordnet::wuPalmer("chair", "chair"), 1.0);
  EXPECT_GT(*wordnet::wuPalmer("armchair", "chair"), *wordnet::wuPalmer("armchair", "bed"));
  EXPECT_FALSE(wordnet::wuPalmer("zorblax", "chair"));
}

TEST(WordNet, AdjectiveClusters) {
  // A satellite's words, then its cluster head's: exhausted is one of the tired cluster.
  const auto exhausted = wordnet::adjectiveClustersOf("exhausted", 1);
  ASSERT_EQ(exhausted.size(), 1u);
  EXPECT_EQ(exhausted[0].front(), "exhausted");
  EXPECT_TRUE(contains(exhausted[0], "worn out"));  // underscores read as spaces
  EXPECT_EQ(exhausted[0].back(), "tired");
  EXPECT_EQ(wordnet::adjectiveClustersOf("drowsy", 1).at(0).back(), "asleep");  // "asleep(p)"
  // A head is its own cluster; morphology: sleepier -> sleepy.
  EXPECT_EQ(wordnet::adjectiveClustersOf("tired", 1).at(0), std::vector<std::string>{"tired"});
  EXPECT_EQ(wordnet::adjectiveClustersOf("sleepier", 1).at(0).front(), "sleepy");
  // Senses in frequency order: chilly is first unemotional, then cold.
  const auto chilly = wordnet::adjectiveClustersOf("chilly", 2);
  ASSERT_EQ(chilly.size(), 2u);
  EXPECT_FALSE(contains(chilly[0], "cold"));
  EXPECT_TRUE(contains(chilly[1], "cold"));
  EXPECT_TRUE(wordnet::adjectiveClustersOf("sofa", 2).empty());
  EXPECT_TRUE(wordnet::adjectiveClustersOf("", 2).empty());
}

TEST(WordNet, VerbAndAdjectiveGlosses) {
  // A verb's senses in frequency order, after morphology: "freezing" is to freeze, whose first
  // senses are to stop moving, to change to ice, and to be cold.
  const auto freezing = wordnet::verbGlossesOf("freezing", 3);
  ASSERT_EQ(freezing.size(), 3u);
  EXPECT_EQ(freezing[2], "be cold");
  EXPECT_EQ(wordnet::verbGlossesOf("starving", 1).at(0).rfind("be hungry", 0), 0u);
  EXPECT_EQ(wordnet::verbGlossesOf("parch", 5).size(), 1u);  // it has one sense
  EXPECT_TRUE(wordnet::verbGlossesOf("zorblax", 2).empty());
  EXPECT_TRUE(wordnet::verbGlossesOf("sleep", 0).empty());
  // Adjectives: no morphology, most frequent first.
  const auto hungry = wordnet::adjectiveGlossesOf("hungry", 2);
  ASSERT_FALSE(hungry.empty());
  EXPECT_NE(hungry[0].find("to eat"), std::string::npos);
  EXPECT_TRUE(wordnet::adjectiveGlossesOf("sofa", 2).empty());
}

TEST(WordNet, MultiWordLabels) {
  EXPECT_EQ(wordnet::labelTokens("DiningTable"), (std::vector<std::string>{"dining", "table"}));
  EXPECT_EQ(wordnet::labelTokens("TVStand"), (std::vector<std::string>{"tv", "stand"}));
  EXPECT_EQ(wordnet::labelTokens("chest_of-drawers"), (std::vector<std::string>{"chest", "of", "drawers"}));
  auto dining = wordnet::resolveLabel("dining table");
  ASSERT_TRUE(dining);
  EXPECT_EQ(dining->sense.lemma, "dining table");  // the compound, not the head noun
  EXPECT_TRUE(dining->modifiers.empty());
  EXPECT_EQ(wordnet::resolveLabel("ArmChair")->sense.lemma, "armchair");  // joined compound
  auto office = wordnet::resolveLabel("office chair");
  ASSERT_TRUE(office);
  EXPECT_EQ(office->sense.offset, wordnet::lookupNoun("chair")->offset);  // head noun
  EXPECT_EQ(office->modifiers, std::vector<std::string>{"office"});
  EXPECT_TRUE(wordnet::namesAnimal("dog"));  // though lookupNoun("dog") is the andiron
  EXPECT_TRUE(wordnet::namesAnimal("cats"));
  EXPECT_FALSE(wordnet::namesAnimal("guest"));
  EXPECT_FALSE(wordnet::namesAnimal("office"));
  EXPECT_FALSE(wordnet::namesAnimal("zorblax"));
}

TEST(WordNetEncoder, SynonymsCoincide) {
  WordNetTextEncoder e;
  EXPECT_NEAR(cos(e, "couch", "sofa"), 1.0, 1e-6);
  EXPECT_NEAR(cos(e, "chest_of_drawers", "dresser"), 1.0, 1e-6);
  EXPECT_NEAR(cos(e, "bed", "bed"), 1.0, 1e-6);
  EXPECT_NEAR(cos(e, "ArmChair", "armchair"), 1.0, 1e-6);
}

TEST(WordNetEncoder, TaxonomyOrdersSimilarity) {
  WordNetTextEncoder e;
  EXPECT_GT(cos(e, "armchair", "chair"), cos(e, "armchair", "bed"));
  // The paper's semantic threshold 0.75 keeps a chair relabelled "armchair" as the same object
  // and separates different furniture.
  EXPECT_GT(cos(e, "armchair", "chair"), 0.75);
  EXPECT_LT(cos(e, "chair", "bed"), 0.75);
  EXPECT_LT(cos(e, "chair", "sofa"), 0.75);
  EXPECT_LT(cos(e, "bed", "sofa"), 0.75);
  EXPECT_LT(cos(e, "chair", "plant"), 0.3);
  EXPECT_GT(cos(e, "chair", "stool"), cos(e, "chair", "plant"));
  // A modifier nudges but does not change the object type.
  EXPECT_GT(cos(e, "office chair", "chair"), 0.9);
  EXPECT_LT(cos(e, "office chair", "chair"), 0.999);
  // ...unless it names an animal the object is for: a dog bed is no answer to "find a bed"
  // (below the default goal_similarity 0.85), though still nearer to a bed than a sofa is.
  EXPECT_LT(cos(e, "dog bed", "bed"), 0.85);
  EXPECT_GT(cos(e, "dog bed", "bed"), cos(e, "sofa", "bed"));
  EXPECT_GT(cos(e, "guest bed", "bed"), 0.9);  // a person's bed stays a bed
}

TEST(WordNetEncoder, UnitVectorsOfConfiguredSizeAndDeterministic) {
  WordNetTextEncoder a(512), b(512);
  for (const char* w : {"chair", "bed", "dining table", "zorblax", "", "!!"}) {
    const Embedding v = a.encode(w);
    ASSERT_EQ(v.size(), 512);
    EXPECT_NEAR(v.norm(), 1.0, 1e-5) << w;
    EXPECT_EQ(v, b.encode(w)) << w;
  }
  EXPECT_EQ(WordNetTextEncoder(64).encode("chair").size(), 64);
}

TEST(WordNetEncoder, UnknownWordsFallBackToNgrams) {
  WordNetTextEncoder e;
  EXPECT_EQ(e.encode("zorblax"), ngramEmbedding("zorblax", 512));
  EXPECT_GT(cos(e, "zorblax", "zorblaxes"), 0.6);
  EXPECT_LT(cos(e, "zorblax", "chair"), 0.3);
  EXPECT_LT(cos(e, "zorblax", "quintophan"), 0.3);
}

TEST(WordNetEncoder, MissingDatabaseFallsBackWithoutCrashing) {
  const auto dir = wordnet::searchDir();
  EXPECT_FALSE(wordnet::reopen("/nonexistent/wordnet"));
  WordNetTextEncoder e;
  EXPECT_FALSE(e.usingWordNet());
  EXPECT_EQ(e.encode("chair"), ngramEmbedding("chair", 512));
  EXPECT_TRUE(wordnet::glossOf("bed").empty());
  EXPECT_TRUE(wordnet::hypernymsOf("bed").empty());
  EXPECT_TRUE(wordnet::reopen(dir));
  EXPECT_NE(wordnet::glossOf("bed").find("sleep"), std::string::npos);
}

TEST(WordNetEncoder, ThreadSafe) {
  WordNetTextEncoder shared;
  const std::vector<std::string> words{"chair", "bed", "sofa", "table", "lamp", "sink", "toilet", "plant"};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      for (int r = 0; r < 5; ++r)
        for (const auto& w : words) shared.encode(w);
    });
  for (auto& t : threads) t.join();
  WordNetTextEncoder serial;
  for (const auto& w : words) EXPECT_EQ(shared.encode(w), serial.encode(w)) << w;
}

TEST(NgramEncoder, CharacterTrigrams) {
  NgramTextEncoder e(256);
  EXPECT_EQ(e.encode("chair").size(), 256);
  EXPECT_NEAR(e.encode("chair").norm(), 1.0, 1e-5);
  EXPECT_NEAR(cos(e, "chair", "chair"), 1.0, 1e-6);
  EXPECT_GT(cos(e, "chair", "chairs"), 0.6);
  // No taxonomy: synonyms are unrelated strings.
  EXPECT_LT(cos(e, "couch", "sofa"), 0.3);
}

TEST(TextEncoderFactory, ByName) {
  EXPECT_EQ(makeTextEncoder("wordnet")->name(), "wordnet");
  EXPECT_EQ(makeTextEncoder("ngram", 128)->dim(), 128);
  PerceptionConfig cfg;
  EXPECT_EQ(makeTextEncoder(cfg)->dim(), cfg.embedding_dim);
  try {
    makeTextEncoder("clip");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("perception.text_encoder"), std::string::npos);
  }
  EXPECT_DOUBLE_EQ(cosineSimilarity(Embedding::Zero(4), Embedding::Ones(4)), 0.0);
  EXPECT_DOUBLE_EQ(cosineSimilarity(Embedding::Ones(4), Embedding::Ones(3)), 0.0);
}
