// Free-text instructions read with the commonsense priors: named objects, room constraints,
// functional requests through WordNet, objects seen judged against a request, how one feels,
// and the judged request lists.

#include <gtest/gtest.h>

#include "support/test_priors.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <tuple>

#include "ussnav/core/error.hpp"
#include "ussnav/perception/wordnet.hpp"
#include "ussnav/reasoning/instruction.hpp"
#include "ussnav/reasoning/priors.hpp"

using namespace ussnav;

namespace {

using test::priors;

bool contains(const std::vector<std::string>& v, const std::string& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

// The first target the instruction reader gives for text ("" when none).
std::string first(const char* text) {
  const Instruction I = interpretInstruction(text, *priors());
  return I.targets.empty() ? std::string() : I.targets.front();
}

}  // namespace

TEST(Instruction, NamedObjects) {
  const auto& P = *priors();
  for (const char* text : {"bed", "find a bed", "Find the BED!", "go to the bed please"}) {
    const Instruction I = interpretInstruction(text, P);
    EXPECT_EQ(I.how, "named") << text;
    ASSERT_EQ(I.targets.size(), 1u) << text;
    EXPECT_EQ(I.targets[0], "bed") << text;
    EXPECT_TRUE(I.room.empty()) << text;
  }
  EXPECT_EQ(interpretInstruction("a dining table", P).targets.at(0), "dining table");
}

TEST(Instruction, RoomConstraint) {
  const Instruction I = interpretInstruction("the sofa in the living room", *priors());
  ASSERT_EQ(I.targets.size(), 1u);
  EXPECT_EQ(I.targets[0], "sofa");
  EXPECT_EQ(I.room, "living room");
  const Instruction K = interpretInstruction("go to the kitchen", *priors());
  EXPECT_EQ(K.how, "room_only");
  EXPECT_TRUE(K.targets.empty());
  EXPECT_EQ(K.room, "kitchen");
}

TEST(Instruction, FunctionalRequestsFindTheirCategoriesThroughGlosses) {
  const Instruction S = interpretInstruction("somewhere to sleep", *priors());
  EXPECT_EQ(S.how, "functional");
  ASSERT_FALSE(S.targets.empty());
  EXPECT_EQ(S.targets, std::vector<std::string>{"bed"});  // not the pillow of a "sleeping person"
  EXPECT_EQ(S.room_hint, "bedroom");
  const Instruction M = interpretInstruction("I want to attend a meeting", *priors(), {"chair", "conference table", "bed"});
  EXPECT_EQ(M.how, "functional");
  EXPECT_TRUE(contains(M.targets, "conference table"));
  EXPECT_FALSE(contains(M.targets, "bed"));
  EXPECT_EQ(M.room_hint, "meeting room");
  // Room descriptions (room_types.tsv) are written as purposes: a kitchen is for cooking.
  EXPECT_EQ(interpretInstruction("somewhere to cook", *priors()).room_hint, "kitchen");
  EXPECT_EQ(interpretInstruction("somewhere to eat", *priors()).room_hint, "dining room");
}

TEST(Instruction, AVerbIsAnActionNotTheObjectSought) {
  // WordNet has a watch, a print, a wash and a store among its artifacts, and the text encoder
  // puts "use toilet" and "read book" within 0.9 of toilet and book: before verbs were told
  // apart, "watch tv" looked for a wristwatch and "I need to use the toilet" for a "use toilet".
  const auto& P = *priors();
  const auto targets = [&](const char* text) { return interpretInstruction(text, P).targets; };
  using V = std::vector<std::string>;
  // "tv" names no category of the priors (their TVs are "tv monitor"s, "for monitoring the
  // program being broadcast", and to monitor is to watch); it stays a target after them.
  EXPECT_EQ(targets("watch tv"), (V{"tv monitor", "tv"}));
  EXPECT_EQ(targets("I want to watch tv"), (V{"tv monitor", "tv"}));
  EXPECT_EQ(targets("I need to use the toilet"), V{"toilet"});
  EXPECT_EQ(targets("I want to read a book"), V{"book"});
  EXPECT_EQ(targets("I want to sit on the sofa"), V{"sofa"});
  // The verb and the object together name another category better than the object alone.
  const Instruction W = interpretInstruction("I need to wash clothes", P);
  EXPECT_EQ(W.how, "functional");
  EXPECT_TRUE(contains(W.targets, "washing machine"));
  EXPECT_FALSE(contains(W.targets, "clothes"));
  // A verb counts in a gloss only where the gloss uses it as one: a book is "a written work",
  // not somewhere to work; an office is "a room where ... work is done".
  const Instruction Q = interpretInstruction("a quiet place to work", P);
  EXPECT_FALSE(contains(Q.targets, "book"));
  EXPECT_EQ(Q.room_hint, "office");
  EXPECT_FALSE(contains(targets("where can I store food"), "store"));
  // A chair and a sofa are seats, and a seat is "furniture that is designed for sitting on" (the
  // nearest hypernym's gloss); seating, "an area ... where several people can sit", says less.
  const auto sit = targets("somewhere to sit");
  EXPECT_TRUE(contains(sit, "chair"));
  EXPECT_TRUE(contains(sit, "sofa"));
  // Among equally good categories the plainest comes first.
  EXPECT_EQ(targets("somewhere to shower").at(0), "shower");
  // A verb that is a thing's own name serves only when WordNet makes the thing from the act: a
  // shower (the fixture) is to shower, a vacuum cleaner to vacuum; a watch (the timepiece) is
  // not to watch, so "watch a movie" no longer looks for one.
  EXPECT_TRUE(wordnet::nounOfVerb("shower", "shower"));
  EXPECT_TRUE(wordnet::nounOfVerb("vacuum", "vacuum"));
  EXPECT_FALSE(wordnet::nounOfVerb("watch", "watch"));
  EXPECT_FALSE(wordnet::nounOfVerb("sofa", "watch"));
  const Instruction M = interpretInstruction("I want to watch a movie", P);
  EXPECT_FALSE(contains(M.targets, "watch"));
  EXPECT_FALSE(servesRequest(M, "watch"));
  EXPECT_TRUE(servesRequest(interpretInstruction("I want to shower", P), "shower"));
  // A WordNet compound that starts with a verb form is still a named object.
  for (const char* text : {"washing machine", "dining table", "a dining table"}) {
    const Instruction N = interpretInstruction(text, P);
    EXPECT_EQ(N.how, "named") << text;
    EXPECT_EQ(N.targets.size(), 1u) << text;
    EXPECT_TRUE(N.room_hint.empty()) << text;
  }
  EXPECT_TRUE(wordnet::knownAsVerb("prints"));
  EXPECT_TRUE(wordnet::knownAsVerb("watching"));
  EXPECT_FALSE(wordnet::knownAsVerb("sofa"));
}

// Session 51. A thing named that is itself what the act is done with is sought, not what does
// the act elsewhere: a piano "is played by depressing keys", so "play the piano" looks for a
// piano (it looked for a tennis racket, "used to play tennis"). And a tool called by the act's
// own word is a candidate when that is what the word first means: a mop is first "a cleaning
// implement" (the floor was a dish sponge's to mop); a print is first a printed text, and a
// work an activity, so printing and working find a printer and an office as before.
TEST(Instruction, AThingNamedForTheActIsWhatTheActNeeds) {
  const auto& P = *priors();
  EXPECT_EQ(first("I want to play the piano"), "piano");
  EXPECT_EQ(first("I want to play the guitar"), "guitar");
  EXPECT_EQ(interpretInstruction("I want to play the piano", P).how, "named");
  // The named thing whose gloss does not use the act still leaves the search to what does it.
  EXPECT_EQ(first("I want to cook dinner"), "pan");
  EXPECT_EQ(first("I need to wash clothes"), "washing machine");
  EXPECT_EQ(first("I need to mop the floor"), "mop");
  EXPECT_EQ(first("I need to comb my hair"), "comb");
  EXPECT_EQ(first("I need to print a document"), "printer");
  const Instruction W = interpretInstruction("somewhere to work", P);
  EXPECT_FALSE(contains(W.targets, "work"));
  EXPECT_EQ(W.room, "office");
  EXPECT_FALSE(contains(interpretInstruction("heat up my lunch", P).targets, "heat"));
  // A thing is named by words said together: "water the plants" names no water plant (an
  // aquatic plant, which WordNet has), nor "flush the toilet" a flush toilet.
  EXPECT_EQ(first("water the plants"), "watering can");
  EXPECT_EQ(first("I want to flush the toilet"), "toilet");
  EXPECT_EQ(first("I want to take a nap on the couch"), "couch");
  EXPECT_EQ(first("I need to wash the dishes"), "dishwasher");
  // A light verb and a meal that is a verb too: to have breakfast is to "eat an early morning
  // meal" (it looked for breakfast itself); to take out the trash is not to trash it.
  EXPECT_EQ(first("I want to have breakfast"), "dining table");
  EXPECT_EQ(first("I need to take out the trash"), "garbage can");
}

TEST(Instruction, APartOfTheBodyIsNotTheThingSought) {
  // WordNet lists a clock's hands and a saw's teeth among its artifacts, so "hands" and "teeth"
  // were read as things to look for. Their usual sense is the body part: the requester's own.
  EXPECT_EQ(wordnet::usualNounLexfile("hands"), "noun.body");  // read from "hand"
  EXPECT_EQ(wordnet::usualNounLexfile("teeth"), "noun.body");
  EXPECT_EQ(wordnet::usualNounLexfile("bed"), "noun.artifact");
  EXPECT_EQ(wordnet::usualNounLexfile("zorblax"), "");
  const auto& P = *priors();
  const Instruction H = interpretInstruction("somewhere to wash my hands", P);
  EXPECT_EQ(H.how, "functional");
  EXPECT_FALSE(contains(H.targets, "hands"));
  EXPECT_TRUE(contains(H.targets, "hand towel"));
  // The act is on the hands, so a thing that answers the act alone does not serve: no washing
  // machine (it did when the hands were no longer a named object and nothing else changed).
  EXPECT_FALSE(contains(H.targets, "washing machine"));
  EXPECT_FALSE(servesRequest(H, "washing machine"));
  for (const char* text : {"I want to brush my teeth", "somewhere to wash my face", "I want to dry my hair"}) {
    const Instruction B = interpretInstruction(text, P);
    for (const char* part : {"teeth", "face", "hair"}) EXPECT_FALSE(contains(B.targets, part)) << text;
  }
  // "Chest" is a thorax before it is a box: the request finds the chest of drawers by its
  // synonyms instead.
  EXPECT_TRUE(contains(interpretInstruction("find a chest", P).targets, "dresser"));
  // Things stay things.
  EXPECT_EQ(interpretInstruction("find my glasses", P).how, "named");
  EXPECT_EQ(interpretInstruction("find the hand towel", P).targets, std::vector<std::string>{"hand towel"});
}

// A functional request names categories of the priors' vocabulary; an object seen with a label
// outside it is judged by the same score (servesRequest): before, "somewhere to cook" looked
// for a pan only, and in a generated apartment, which has a stove and no pan, found nothing.
TEST(Instruction, ObjectsSeenAreJudgedAgainstAFunctionalRequest) {
  const auto& P = *priors();
  const auto targets = [&](const char* text) { return interpretInstruction(text, P).targets; };
  const Instruction cook = interpretInstruction("somewhere to cook", P);
  ASSERT_EQ(cook.how, "functional");
  EXPECT_GT(cook.score, 0.0);
  EXPECT_FALSE(contains(cook.targets, "stove"));  // not a category of the tables
  EXPECT_TRUE(servesRequest(cook, "stove"));       // "a kitchen appliance used for cooking food"
  EXPECT_FALSE(servesRequest(cook, "bed"));
  EXPECT_FALSE(servesRequest(cook, "sofa"));
  const Instruction sit = interpretInstruction("somewhere to sit", P);
  for (const char* seat : {"sofa", "chair", "office chair", "stool"}) EXPECT_TRUE(servesRequest(sit, seat)) << seat;
  EXPECT_FALSE(servesRequest(sit, "fridge"));
  // A dog bed is no place for a person to sleep (ProcTHOR's house_0 has one, and no bed nearer).
  const Instruction sleep = interpretInstruction("somewhere to sleep", P);
  EXPECT_TRUE(servesRequest(sleep, "bed"));
  EXPECT_TRUE(servesRequest(sleep, "guest bed"));
  EXPECT_FALSE(servesRequest(sleep, "dog bed"));
  // A light verb and an act ask for what the act needs, when the noun names no category: WordNet's
  // first artifact "bath" is a laboratory vessel, its act "you soak and wash your body in a bathtub".
  EXPECT_EQ(targets("I want to take a bath"), std::vector<std::string>{"bathtub"});
  EXPECT_EQ(targets("take a nap"), std::vector<std::string>{"bed"});
  EXPECT_EQ(targets("I want to take a shower"), std::vector<std::string>{"shower"});  // a category itself
  // So does wanting or needing one (session 47): "I need a nap" was the literal "nap", "I want a
  // drink" the literal "drink"; a thing one wants that is a category stays that thing.
  EXPECT_EQ(targets("I need a nap"), std::vector<std::string>{"bed"});
  EXPECT_EQ(targets("I need a bath"), std::vector<std::string>{"bathtub"});
  EXPECT_EQ(interpretInstruction("I want a drink", P).targets.at(0), "cup");
  EXPECT_EQ(interpretInstruction("I want a bed", P).how, "named");
  EXPECT_EQ(targets("I need a towel"), std::vector<std::string>{"towel"});
  EXPECT_FALSE(servesRequest(sit, "toilet paper"));
  // The fridge's own gloss is about its motor; its hypernym's is "white goods in which food can
  // be stored at low temperatures" (was: a bottle, "used for storing drinks").
  EXPECT_EQ(interpretInstruction("where can I store food", P).targets, std::vector<std::string>{"fridge"});
  // A name's -ing word says what the thing is for: to dine is to "have supper; eat dinner".
  EXPECT_NE(wordnet::verbGlossOf("dining").find("eat"), std::string::npos) << wordnet::verbGlossOf("dining");
  EXPECT_TRUE(wordnet::verbGlossOf("sofa").empty());
  EXPECT_FALSE(servesRequest(interpretInstruction("somewhere to wash my hands", P), "plunger"));  // a "hand tool"
  const Instruction eat = interpretInstruction("somewhere to eat", P);
  EXPECT_TRUE(contains(eat.targets, "dining table"));
  EXPECT_TRUE(servesRequest(eat, "dining table"));
  EXPECT_FALSE(servesRequest(eat, "bed"));
  // Named requests are matched by the text encoder alone.
  const Instruction bed = interpretInstruction("bed", P);
  EXPECT_EQ(bed.how, "named");
  EXPECT_FALSE(servesRequest(bed, "bed"));
  EXPECT_DOUBLE_EQ(requestScore(bed, "bed"), 0.0);
}

// "Somewhere to VERB OBJECT": a place for the act on the object. The objects that answer it are
// seldom in the priors' vocabulary (a wardrobe, a coat rack, a bookshelf are in none of the
// tables), so the request is judged; and the act is often written with other words in the
// gloss (a dresser is "for keeping clothes", a wardrobe "provides storage space for clothes").
// Before, each of these looked for the object itself: the clothes, the coat, the books.
TEST(Instruction, APlaceForAnActOnAnObjectIsJudgedByTheActAndTheObject) {
  const auto& P = *priors();
  const Instruction store = interpretInstruction("somewhere to store clothes", P);
  ASSERT_EQ(store.how, "functional");
  EXPECT_TRUE(store.object_named);
  EXPECT_TRUE(contains(store.targets, "dresser"));  // to store is to keep (WordNet's hypernym)
  EXPECT_FALSE(contains(store.targets, "clothes"));
  EXPECT_TRUE(servesRequest(store, "wardrobe"));      // "storage": the noun of the verb
  EXPECT_TRUE(servesRequest(store, "dresser"));
  EXPECT_FALSE(servesRequest(store, "clothes dryer"));  // names the clothes, not the act
  EXPECT_FALSE(servesRequest(store, "shower curtain"));  // a "hanging cloth": clothes are no cloths
  const Instruction coat = interpretInstruction("somewhere to hang my coat", P);
  ASSERT_EQ(coat.how, "functional");
  EXPECT_TRUE(servesRequest(coat, "coat rack"));
  EXPECT_FALSE(servesRequest(coat, "bed"));
  const Instruction books = interpretInstruction("somewhere to put my books", P);
  ASSERT_EQ(books.how, "functional");
  EXPECT_TRUE(servesRequest(books, "bookshelf"));  // a closed compound, named for books
  EXPECT_FALSE(servesRequest(books, "bed"));
  // A watch is no place to watch tv: a request that names its object is answered by things
  // that answer the object.
  const Instruction tv = interpretInstruction("somewhere to watch tv", P);
  EXPECT_TRUE(contains(tv.targets, "tv"));
  EXPECT_TRUE(servesRequest(tv, "tv monitor"));
  EXPECT_FALSE(servesRequest(tv, "watch"));
  EXPECT_TRUE(servesRequest(interpretInstruction("where can I wash the dishes", P), "dishwasher"));
  // Without a place word the object named is still the target ("read a book" is the book).
  EXPECT_EQ(interpretInstruction("I want to read a book", P).how, "named");
  // "Keep food cold": a refrigerator is where food "can be stored", and to store is to keep;
  // a dresser keeps clothes, not food (was: dresser, watch, chest of drawers).
  EXPECT_EQ(interpretInstruction("I need to keep food cold", P).targets, std::vector<std::string>{"fridge"});
  // Kin alone is no answer: a bottle "can be capped", and to cap is to "lie at the top of".
  EXPECT_FALSE(servesRequest(interpretInstruction("somewhere to lie down", P), "bottle"));
  // A kind of a seat serves "somewhere to sit" as a seat does, through what a seat is for; a
  // plunger, a "hand tool", still serves no "wash my hands".
  const Instruction sit = interpretInstruction("somewhere to sit", P);
  EXPECT_TRUE(servesRequest(sit, "armchair"));
  EXPECT_FALSE(servesRequest(sit, "toilet paper"));
  // A plural WordNet also lists in no physical sense means its singular: "shoes" is footwear,
  // not "a particular situation".
  ASSERT_TRUE(wordnet::lookupNoun("shoes"));
  EXPECT_EQ(wordnet::lookupNoun("shoes")->lexfile, "noun.artifact");
  EXPECT_TRUE(servesRequest(interpretInstruction("where can I keep my shoes", P), "shoe cabinet"));
  const wordnet::VerbKin kin = wordnet::verbKin("stored");
  EXPECT_TRUE(contains(kin.verbs, "keep"));
  EXPECT_TRUE(contains(kin.nouns, "storage"));
  EXPECT_TRUE(wordnet::verbKin("sofa").verbs.empty());
}

TEST(Instruction, VerbsAdjectivesAndPhrasalVerbsAreReadThroughWordNet) {
  const auto& P = *priors();
  // To sleep is to rest, to rest is to lie (verb hypernyms): a bed, "a place to sleep", serves
  // lying down and napping (to nap is to sleep). Was: a laundry hamper (a hamper is a shackle
  // "used to tie down") and the literal "nap".
  EXPECT_EQ(first("I want to lie down"), "bed");
  EXPECT_EQ(first("I want to nap"), "bed");
  EXPECT_EQ(first("I'd like to take a nap"), "bed");  // a nap is a sleep first, no thing
  EXPECT_FALSE(servesRequest(interpretInstruction("I want to lie down", P), "laundry hamper"));
  // A state read through its adjective's definition: hungry is "a desire to eat food".
  const Instruction hungry = interpretInstruction("I'm hungry", P);
  EXPECT_EQ(hungry.how, "functional");
  EXPECT_TRUE(contains(hungry.targets, "dining table"));
  EXPECT_EQ(hungry.room_hint, "dining room");
  const std::string thirsty = first("I am thirsty");
  EXPECT_TRUE(thirsty == "cup" || thirsty == "mug") << thirsty;
  // A phrasal verb closed up into an act: "work out" -> workout, exercise; a dumbbell is "an
  // exercising weight". Was: a shower curtain.
  // A particle after a light verb goes too: "take out the trash" is about the trash, not "an
  // out" ("a failure by a batter ... to reach a base safely"). Was: a plate, a baseball bat.
  EXPECT_EQ(first("I need to take out the trash"), "garbage can");
  const Instruction gym = interpretInstruction("I want to work out", P);
  EXPECT_EQ(gym.targets.front(), "dumbbell");
  EXPECT_EQ(gym.room_hint, "gym");
  // What the act is on is no category: the things doing the act are sought.
  const Instruction cook = interpretInstruction("I want to cook dinner", P);  // was: "dinner"
  EXPECT_EQ(cook.how, "functional");
  EXPECT_EQ(cook.targets.front(), "pan");
  EXPECT_TRUE(servesRequest(cook, "stove"));
  EXPECT_FALSE(servesRequest(cook, "dining table"));  // names dinner, cooks nothing
  const Instruction clean = interpretInstruction("clean the floor", P);
  EXPECT_EQ(clean.targets.front(), "vacuum cleaner");  // a vacuum CLEANER: derived from to clean
  EXPECT_FALSE(servesRequest(clean, "floor lamp"));
  // A thing WordNet derives from the act, outside the vocabulary, when no category does the act
  // by name or purpose ("print" -> printer) ...
  EXPECT_EQ(first("I need to print a document"), "printer");  // was: "document"
  // ... and only then: a kettle is "a pot for stewing or boiling", a boiler only serves.
  const Instruction boil = interpretInstruction("boil water", P);
  EXPECT_EQ(boil.targets.front(), "kettle");
  EXPECT_TRUE(servesRequest(boil, "boiler"));
  // Nor is a place derived from the act a thing to look for: a brewery brews no tea.
  EXPECT_FALSE(contains(interpretInstruction("I want to brew some tea", P).targets, "brewery"));
  // A general verb names no act: "make" coffee is not a light switch "for making or breaking a
  // connection".
  EXPECT_FALSE(contains(interpretInstruction("I want to make coffee", P).targets, "light switch"));
  // A WordNet compound of what the act is on and the act's noun or doer is the thing for it,
  // outside the vocabulary too (was: the dishes, a scrub brush, a watering can, "coffee").
  EXPECT_EQ(first("where can I wash the dishes"), "dishwasher");
  EXPECT_EQ(first("brush my teeth"), "toothbrush");
  EXPECT_EQ(first("heat water"), "water heater");
  EXPECT_EQ(first("I want to make coffee"), "coffee maker");
  EXPECT_EQ(first("I want to dry my clothes"), "clothes dryer");  // a category: no "clothes drier" beside it
  EXPECT_EQ(interpretInstruction("I want to dry my clothes", P).targets.size(), 1u);
  // A noun of the act as a purpose: a toilet is "for defecation and urination" (was: "pee").
  EXPECT_EQ(first("I need to pee"), "toilet");
  // Among equals, the one named for the act: a WASHING machine before a clothes dryer, "a dryer
  // that dries clothes wetted by washing" (both 3.5).
  EXPECT_EQ(first("I need to wash my clothes"), "washing machine");

  EXPECT_TRUE(contains(wordnet::verbAncestors("sleep", 3), "rest"));
  EXPECT_TRUE(contains(wordnet::verbAncestors("sleeping", 3), "lie"));
  EXPECT_TRUE(wordnet::verbAncestors("zorblax", 3).empty());
  EXPECT_EQ(wordnet::phrasalVerb("lying", "down"), "lie down");
  EXPECT_EQ(wordnet::phrasalVerb("sofa", "down"), "");
  ASSERT_FALSE(wordnet::adjectiveGlossesOf("hungry", 2).empty());
  EXPECT_NE(wordnet::adjectiveGlossesOf("hungry", 2).front().find("to eat"), std::string::npos);
  EXPECT_EQ(wordnet::pickedSenseRank("tv"), 1);
  EXPECT_GT(wordnet::pickedSenseRank("rest"), 1);
  EXPECT_EQ(wordnet::pickedSenseRank("zorblax"), -1);
  EXPECT_TRUE(contains(wordnet::nounForms("teeth"), "tooth"));
  EXPECT_EQ(wordnet::nounForms("dishes"), std::vector<std::string>{"dish"});
  EXPECT_TRUE(wordnet::nounForms("zorblax").empty());
  EXPECT_TRUE(wordnet::namesPlace("brewery"));
  EXPECT_FALSE(wordnet::namesPlace("kettle"));
}

// Session 43: three readings of WordNet that each had a request wrong.
TEST(Instruction, KindsOfAThingTiesAndTheSenseOfAnIngWord) {
  const auto& P = *priors();
  // What a kind of the thing is for, at 0.8: a sink may be a washbasin, "where you can wash your
  // hands and face", a pot a teapot, "for brewing tea". Before, a hand towel (its name has the
  // hand; it dries) and the tea itself.
  const auto kinds = wordnet::kindGlossesOf("sink");
  EXPECT_TRUE(std::any_of(kinds.begin(), kinds.end(), [](const std::string& g) { return g.find("wash your hands") != std::string::npos; }));
  EXPECT_TRUE(wordnet::kindGlossesOf("office chair").empty());  // known by its head noun only
  const Instruction W = interpretInstruction("wash my hands", P);
  ASSERT_FALSE(W.targets.empty());
  EXPECT_EQ(W.targets.front(), "sink");
  // A sink seen matches as a target; a washbasin seen serves by its own gloss.
  EXPECT_TRUE(servesRequest(W, "washbasin"));
  EXPECT_FALSE(servesRequest(W, "washing machine"));
  const Instruction T = interpretInstruction("I want to brew some tea", P);
  EXPECT_EQ(T.how, "functional");
  EXPECT_EQ(T.targets, std::vector<std::string>{"pot"});
  // A label inherits what its hypernym's own gloss is for, not what the hypernym's kinds are for:
  // those are its siblings. A microwave is a kitchen appliance, which may be a refrigerator, and
  // keeps no food cold; a spoon is cutlery and a box a container, and neither stores food (all
  // three served before the hypernym's kinds were left out).
  const Instruction K = interpretInstruction("I need to keep food cold", P);
  EXPECT_TRUE(servesRequest(K, "fridge"));
  EXPECT_FALSE(servesRequest(K, "microwave"));
  const Instruction S = interpretInstruction("where can I store food", P);
  EXPECT_TRUE(servesRequest(S, "fridge"));
  for (const char* label : {"spoon", "box", "cup", "garbage bag"}) EXPECT_FALSE(servesRequest(S, label)) << label;
  // Nor is a label seen judged by its own kinds: a can may be a canister, "for storing dry
  // foods", but the can in the Webots apartment's kitchen is no place to store food (it served,
  // and made "where can I store food" a single-room task there).
  EXPECT_FALSE(servesRequest(S, "can"));
  // Only what a kind is for as a verb counts: a conference table is "usually in a conference
  // room for meetings", a horse cart "used for farm work"; the room is still what is sought.
  EXPECT_EQ(interpretInstruction("I want to attend a meeting", P).room, "meeting room");
  const Instruction O = interpretInstruction("somewhere to work", P);
  EXPECT_EQ(O.how, "room_only");
  EXPECT_EQ(O.room, "office");

  // Among equal scores, what a room is furnished with first: "where can I eat" finds a dining
  // table ("a table at which meals are served") before a fork ("used for serving and eating").
  EXPECT_TRUE(wordnet::furnishes("dining table"));
  EXPECT_TRUE(wordnet::furnishes("sink"));    // a plumbing fixture
  EXPECT_TRUE(wordnet::furnishes("fridge"));  // a home appliance
  EXPECT_FALSE(wordnet::furnishes("fork"));
  EXPECT_FALSE(wordnet::furnishes("zorblax"));
  const Instruction E = interpretInstruction("where can I eat", P);
  EXPECT_DOUBLE_EQ(requestScore(E, "dining table"), requestScore(E, "fork"));
  ASSERT_EQ(E.targets.size(), 2u);
  EXPECT_EQ(E.targets.front(), "dining table");

  // An -ing word of a name gives its verb's gloss as what the thing is for, but only the verbs
  // in it: to shelve is first "to hold back to a later time", and a shelving unit is no place to
  // check the time (it was the first target); to dine is to "eat dinner", and a dining table
  // still answers "I want to eat dinner" first.
  const Instruction C = interpretInstruction("I want to check the time", P);
  ASSERT_FALSE(C.targets.empty());
  EXPECT_EQ(C.targets.front(), "alarm clock");
  EXPECT_LT(requestScore(C, "shelving unit"), requestScore(C, "alarm clock"));
  const Instruction D = interpretInstruction("I want to eat dinner", P);
  ASSERT_FALSE(D.targets.empty());
  EXPECT_EQ(D.targets.front(), "dining table");
  EXPECT_GT(requestScore(D, "dining table"), requestScore(D, "fork"));
}

// Four lists of everyday requests judged by hand (tests/reasoning/data/): the first target must
// be one of the acceptable categories, or name one at the goal's text cosine (0.85: "couch" is
// a sofa), or the room constraint the one given. Session 42 (before it: 20 of 44 and 12 of 38,
// the two answers the dev list gained included; the held-out list read 16 of 38 at its first
// run, 18 after two rules written having seen its misses; a third, fresh list, written after
// the last rule and run once: 11 -> 18 of 30). Session 43's three rules (kinds, ties, -ing
// words): dev 33, held-out 21, fresh 18, and a fourth list written before them reads 14 of 31
// with and without them. A seventh, written at session 51's start, read 16 of 34 then. The
// floors are those counts, as later sessions raised them; the misses are printed, to be read
// and bettered, not to be tuned to.
TEST(Instruction, JudgedRequestsReadAtLeastAsWellAsBefore) {
  const auto& P = *priors();
  const auto judge = [&](const std::string& file) {
    std::ifstream in(std::filesystem::path(USSNAV_SOURCE_DIR) / "tests/reasoning/data" / file);
    EXPECT_TRUE(in.good()) << file;
    int right = 0, total = 0;
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      const auto tab = line.find('\t');
      if (tab == std::string::npos) {
        ADD_FAILURE() << file << ": no tab in '" << line << "'";
        continue;
      }
      const std::string request = line.substr(0, tab);
      std::vector<std::string> ok;
      std::stringstream alts(line.substr(tab + 1));
      for (std::string a; std::getline(alts, a, '|');) ok.push_back(a);
      const Instruction I = interpretInstruction(request, P);
      bool good = false;
      for (const auto& a : ok) {
        if (a.starts_with("room:")) good = good || I.room == a.substr(5);
        else if (!I.targets.empty())
          good = good || I.targets.front() == a || P.encoder().similarity(I.targets.front(), a) >= 0.85;
      }
      ++total;
      right += good;
      if (!good)
        std::cout << "  " << file << ": '" << request << "' -> " << I.how << " "
                  << (I.targets.empty() ? "room " + I.room : I.targets.front()) << "\n";
    }
    std::cout << file << ": " << right << " of " << total << " read right\n";
    return std::pair{right, total};
  };
  // file, requests in it, floor
  const std::tuple<const char*, int, int> lists[] = {{"requests_dev.tsv", 44, 37},
                                                     {"requests_heldout.tsv", 38, 24},
                                                     {"requests_fresh.tsv", 30, 19},
                                                     {"requests_fresh2.tsv", 31, 15},
                                                     {"requests_states.tsv", 20, 18},
                                                     {"requests_parts.tsv", 18, 12},
                                                     {"requests_fresh3.tsv", 34, 17}};
  for (const auto& [file, count, floor] : lists) {
    const auto [right, total] = judge(file);
    EXPECT_EQ(total, count) << file;
    EXPECT_GE(right, floor) << file;
  }
}

// A state's row in states.tsv, as words ("" when it has none).
static std::string request(const CommonsensePriors& P, const std::string& state) {
  const auto* row = P.stateFor(state);
  return row ? row->request : std::string();
}
static std::string act(const CommonsensePriors& P, const std::string& state) {
  const auto* row = P.stateFor(state);
  return row ? row->act : std::string();
}

TEST(Instruction, HowOneFeelsIsReadAsWhatOneAsksFor) {
  const auto& P = *priors();
  // states.tsv: tired -> "to sleep". Was: the literal "tired", and "fall" for "sleepy" (its
  // definition, "ready to fall asleep").
  EXPECT_EQ(first("I'm tired"), "bed");
  EXPECT_EQ(first("I feel so sleepy"), "bed");
  EXPECT_EQ(first("I'm bored"), "tv monitor");
  // A word the table lacks takes its WordNet cluster's row: exhausted and weary are tired,
  // drowsy is asleep, filthy is dirty ("to shower or bathe": a shower, and a bathtub serves).
  EXPECT_EQ(request(P, "exhausted"), "to sleep");
  EXPECT_EQ(request(P, "drowsy"), "to sleep");
  EXPECT_EQ(first("I'm weary"), "bed");
  const Instruction filthy = interpretInstruction("I'm filthy", P);
  EXPECT_EQ(filthy.targets.front(), "shower");
  EXPECT_TRUE(servesRequest(filthy, "bathtub"));
  EXPECT_FALSE(servesRequest(filthy, "sink"));
  EXPECT_EQ(first("I'm so very tired"), "bed");  // the words of degree go with the state
  // Through the second sense when the first says nothing: chilly is first unemotional, then cold.
  EXPECT_EQ(request(P, "chilly"), "to warm");
  EXPECT_EQ(request(P, "bed"), "");
  EXPECT_EQ(request(P, "happy"), "");
  // A participle no cluster holds reads through its verb's sense of being in a state: to starve
  // is to "be hungry" (WordNet files the adjective "starving" under underfed), to freeze in its
  // third sense to "be cold", to bake in its fourth to "be very hot". Was: the literal words.
  EXPECT_EQ(request(P, "starving"), "to eat");
  EXPECT_EQ(request(P, "freezing"), "to warm");
  EXPECT_EQ(request(P, "baking"), "to cool");
  EXPECT_EQ(first("I'm starving"), first("I'm hungry"));
  EXPECT_EQ(first("I'm freezing"), first("I'm cold"));
  // A verb whose sense of being is in no row ("sitting": "be seated"; "boiling": "be agitated"),
  // or the verb itself, is no state.
  EXPECT_EQ(request(P, "sitting"), "");
  EXPECT_EQ(request(P, "boiling"), "");
  EXPECT_EQ(request(P, "starve"), "");
  // Only a word that says how someone is: food kept cold is no one feeling cold.
  EXPECT_EQ(first("keep food cold"), "fridge");
  EXPECT_EQ(first("I need to keep food cold"), "fridge");
  const Instruction warm = interpretInstruction("I'm feeling a bit cold", P);
  EXPECT_EQ(warm.how, "functional");
  EXPECT_TRUE(contains(warm.request, "warm")) << warm.request.size();
  EXPECT_FALSE(contains(interpretInstruction("a cold drink", P).request, "warm"));
  // After "is", "are", "getting": only when the subject is a person or someone's.
  EXPECT_FALSE(contains(interpretInstruction("find a drink that is cold", P).request, "warm"));
  EXPECT_TRUE(contains(interpretInstruction("my feet are cold", P).request, "warm"));
  EXPECT_EQ(first("we are tired"), "bed");
  EXPECT_EQ(first("I'm still getting tired"), "bed");
}

TEST(Instruction, AThingInAStateIsWhatTheStatesActIsDoneTo) {
  const auto& P = *priors();
  // states.tsv's act: dirty -> wash, wet -> dry. Was: "my hands are to shower or bathe" (a bathtub).
  EXPECT_EQ(act(P, "dirty"), "wash");
  EXPECT_EQ(act(P, "filthy"), "wash");  // through dirty's cluster
  EXPECT_EQ(act(P, "tired"), "");
  EXPECT_EQ(first("my hands are dirty"), "sink");
  EXPECT_EQ(first("my clothes are really dirty"), "washing machine");
  EXPECT_EQ(first("my hair is wet"), "hair dryer");
  EXPECT_EQ(first("the dishes are dirty"), "dishwasher");
  // An act on one's body is served only by what does the act: a hair dryer is "hand-held".
  EXPECT_FALSE(servesRequest(interpretInstruction("my hands are dirty", P), "hair dryer"));
  EXPECT_FALSE(servesRequest(interpretInstruction("I need to wash my hands", P), "hair dryer"));
  EXPECT_TRUE(servesRequest(interpretInstruction("I need to dry my hair", P), "hair dryer"));
  const Instruction soup = interpretInstruction("the soup is getting cold", P);
  EXPECT_TRUE(contains(soup.request, "warm") && contains(soup.request, "soup"));
  // A person or an animal is in the state itself; a part of one's body without an act stands for
  // the one it belongs to.
  EXPECT_EQ(first("my son is sleepy"), "bed");
  EXPECT_EQ(first("the kids are tired"), "bed");
  EXPECT_TRUE(contains(interpretInstruction("my dog is dirty", P).request, "shower"));
  EXPECT_TRUE(contains(interpretInstruction("my feet are tired", P).request, "sleep"));
  // No one's and nothing's: a relative clause, an adjective before its noun.
  EXPECT_FALSE(contains(interpretInstruction("find a drink that is cold", P).request, "warm"));
  EXPECT_EQ(first("find the dirty dishes"), first("find the dishes"));
}

TEST(Instruction, UnknownWordsAreKeptLiterallyAndEmptyIsRejected) {
  const Instruction Z = interpretInstruction("find the zorblax", *priors());
  EXPECT_EQ(Z.how, "literal");
  EXPECT_EQ(Z.targets, std::vector<std::string>{"zorblax"});
  EXPECT_THROW(interpretInstruction("", *priors()), InputError);
  EXPECT_THROW(interpretInstruction("  find a  ", *priors()), InputError);
  EXPECT_EQ(stemWord("sleeping"), "sleep");
  EXPECT_EQ(stemWord("sitting"), "sit");  // a doubled consonant goes, but not l, s or z
  EXPECT_EQ(stemWord("stopped"), "stop");
  EXPECT_EQ(stemWord("dressing"), "dress");
  EXPECT_EQ(stemWord("falling"), "fall");
  EXPECT_EQ(stemWord("meals"), "meal");
  EXPECT_EQ(stemWord("clothing"), stemWord("clothes"));
  EXPECT_NE(stemWord("cloth"), stemWord("clothes"));
  EXPECT_EQ(instructionWords("Find a BED, now!"), (std::vector<std::string>{"find", "a", "bed", "now"}));
}
