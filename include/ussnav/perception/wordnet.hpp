#pragma once
// Offline word knowledge from Princeton WordNet 3.0 (Debian `wordnet-base` data read through the
// `wordnet-dev` C library): the noun sense an object label most likely means indoors, its
// synonyms, gloss and hypernym chain. The C library keeps global state and is not thread-safe,
// so every call here takes one process-wide mutex. The database is opened lazily on first use;
// when it is missing, available() is false, a warning is logged once and every lookup answers
// "unknown" (callers fall back, nothing throws). Results are cached per synset: after warm-up a
// lookup is a hash probe; a cold one reads a few lines of data.noun.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ussnav::wordnet {

// One ancestor of a synset (itself included) with its depth, root ("entity") = 1.
struct Ancestor {
  long offset = 0;  // byte offset in data.noun: the synset's identity
  int depth = 1;
};

// A noun synset chosen for a label.
struct Sense {
  long offset = 0;                  // identity: equal offsets = synonyms ("couch" == "sofa")
  std::string lemma;                // the synset's first word, spaces for underscores
  std::vector<std::string> lemmas;  // all its words
  std::string gloss;                // definition without the usage examples
  std::string lexfile;              // e.g. "noun.artifact"
  int depth = 1;                    // shortest hypernym path to the root, root = 1
  std::vector<Ancestor> ancestors;  // transitive hypernyms (and instance hypernyms) and itself
};

// Opens the database once (WNSEARCHDIR, else /usr/share/wordnet). Thread-safe.
bool available();
// Where the database was looked for (for messages).
std::filesystem::path searchDir();
// Closes and re-opens the database from `dir` (tests of the missing-data fallback; rarely
// needed otherwise). Returns available().
bool reopen(const std::filesystem::path& dir);

// The sense of a single noun or WordNet compound ("dining_table", "chest of drawers"), after
// morphology ("chairs" -> "chair"). Among the word's senses the first in WordNet's frequency
// order wins within the best tier: (1) artifacts that are not rooms, buildings or building
// complexes ("table" -> furniture, not a data table; "toilet" -> the fixture, not the room),
// (2) other physical entities ("plant" -> flora, not a factory), (3) rooms and buildings
// ("kitchen"), (4) anything else. Senses that are only a proper name ("Monitor", a ship) come
// last. nullopt when the word is not a WordNet noun.
std::optional<Sense> lookupNoun(const std::string& word);
// True when WordNet knows the single word as a verb, after verb morphology ("prints",
// "watching", "ate" -> print, watch, eat). Instructions use it to tell "to print" from a print.
bool knownAsVerb(const std::string& word);
// Definition of the single word's most frequent sense that is an act (lexicographer file
// noun.act): actGlossOf("bath") = "you soak and wash your body in a bathtub", though the
// artifact sense lookupNoun() prefers is a laboratory vessel. Empty when it has none.
std::string actGlossOf(const std::string& word);
// Definition of the single word's most frequent verb sense, after verb morphology:
// verbGlossOf("dining") = "have supper; eat dinner". Empty when WordNet has no such verb.
std::string verbGlossOf(const std::string& word);
// Definitions of the first `senses` senses of the first verb the word is, after verb
// morphology, most frequent first: verbGlossesOf("freezing", 3)[2] = "be cold". Empty when none.
std::vector<std::string> verbGlossesOf(const std::string& word, int senses);
// Words for the act a verb names, to find it in a gloss written with other words (after verb
// morphology; both empty when WordNet has no such verb). `verbs`: the lemmas of its most
// frequent sense and the first lemma of each of that sense's hypernyms ("store" -> store, hive
// away, ..., keep; a dresser is "for keeping clothes"). `nouns`: the nouns WordNet derives from its two most
// frequent senses ("store" -> store, storage, storehouse, ...; a wardrobe "provides storage").
struct VerbKin {
  std::vector<std::string> verbs, nouns;
};
VerbKin verbKin(const std::string& word);
// True when the sense lookupLabel() gives `label` is one WordNet derives from a sense of the verb
// `verb` (or it from the noun): a shower (the fixture) is to shower, an iron (the appliance) to
// iron, but a watch (the timepiece) is not to watch. False when either is unknown.
bool nounOfVerb(const std::string& label, const std::string& verb);
// All words of the hypernyms of the verb's most frequent sense, `levels` steps up, nearest
// first (after verb morphology): verbAncestors("sleep", 3) = {"rest", "recumb", "repose",
// "recline", "lie"}: to sleep is to rest, and to rest is to lie. Empty when unknown.
std::vector<std::string> verbAncestors(const std::string& verb, int levels);
// The base form of a phrasal verb WordNet knows, "" when it knows none: phrasalVerb("lying",
// "down") = "lie down", phrasalVerb("heat", "up") = "heat up".
std::string phrasalVerb(const std::string& verb, const std::string& particle);
// The index nouns a word can be read as: itself, and what noun morphology makes of it:
// "teeth" -> {"teeth", "tooth"}, "dishes" -> {"dish"}. Empty when it is no noun.
std::vector<std::string> nounForms(const std::string& word);
// True when the sense lookupLabel() gives the label is a room, a building or a building complex
// ("brewery", "kitchen"), not a thing in one.
bool namesPlace(const std::string& label);
// True when the label's sense is a piece of furniture, a fixture or a home appliance ("dining
// table", "sink", "fridge"): what a room is furnished with, not a thing carried about ("fork").
bool furnishes(const std::string& label);
// Definitions of the word's first `senses` adjective senses, most frequent first (no
// morphology): adjectiveGlossesOf("hungry", 2)[0] = "feeling hunger; feeling a need or desire
// to eat food". Empty when WordNet has no such adjective.
std::vector<std::string> adjectiveGlossesOf(const std::string& word, int senses);
// The word's first `senses` adjective senses, most frequent first, each as its synset's words
// followed, for a satellite, by its cluster head's ("exhausted": exhausted, dog-tired, ...,
// tired; "drowsy": drowsy, drowsing, dozy, asleep). Adjective morphology applies ("sleepier" ->
// sleepy); underscores read as spaces, markers such as "(p)" dropped. Empty when none.
std::vector<std::vector<std::string>> adjectiveClustersOf(const std::string& word, int senses);
// Lexicographer file of the most frequent sense of the index word lookupNoun() reads the word
// from: "noun.body" for "hands" (read as "hand", whose usual sense is the body part, though
// lookupNoun() picks a clock's hand) and "teeth"; "noun.artifact" for "bed". Empty when the
// word is no WordNet noun.
std::string usualNounLexfile(const std::string& word);
// Where the sense lookupNoun() picks is in WordNet's frequency order of the word's senses, 0 =
// the most frequent: 1 for "tv" (a television receiver; a television broadcast comes first), 5
// for "rest" (a support; a remainder comes first). -1 when the word is no noun.
int pickedSenseRank(const std::string& word);
// True when the word's most frequent noun sense is an animal ("dog", "cats", "pet"; not "guest"
// or "office"), whatever sense lookupNoun() prefers indoors (it reads "dog" as an andiron).
bool namesAnimal(const std::string& word);
// The sense of a free-form object label: lower-cased, CamelCase and '_'/'-' split into words;
// the whole compound is tried first ("dining table" -> dining_table, "ArmChair" -> armchair),
// then the last word (the head noun: "office chair" -> chair). nullopt when none is known.
std::optional<Sense> lookupLabel(const std::string& label);
// lookupLabel() plus the words before the head noun when only the head was found
// ("office chair" -> the sense of "chair", modifiers {"office"}; empty for a compound hit).
struct LabelSense {
  Sense sense;
  std::vector<std::string> modifiers;
};
std::optional<LabelSense> resolveLabel(const std::string& label);

// Tokens of a label as lookupLabel() splits it: "DiningTable" -> {"dining", "table"}.
std::vector<std::string> labelTokens(const std::string& label);

// Definition text of the label's sense, e.g. glossOf("bed") = "a piece of furniture that
// provides a place to sleep". Empty when unknown.
std::string glossOf(const std::string& label);
// First lemma of each hypernym on the shortest path to the root, nearest first:
// hypernymsOf("armchair") = {"chair", "seat", "furniture", ..., "entity"}. Empty when unknown.
std::vector<std::string> hypernymsOf(const std::string& label);
// Definitions of the direct kinds of the label's sense (its hyponyms), in WordNet's order:
// for "sink", a kitchen sink's and a washbasin's ("... where you can wash your hands and
// face"). Empty when unknown, or when the label is known by its head noun only ("office chair").
std::vector<std::string> kindGlossesOf(const std::string& label);
// All words of the label's synset ("couch" -> {"sofa", "couch", "lounge"}). Empty when unknown.
std::vector<std::string> synonymsOf(const std::string& label);
// Wu-Palmer similarity of the two labels' senses, 2 d(lcs) / (d(a) + d(b)), in [0, 1];
// nullopt when either is unknown. The reference the built-in text encoder approximates.
std::optional<double> wuPalmer(const std::string& a, const std::string& b);

}  // namespace ussnav::wordnet
