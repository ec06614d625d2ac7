#pragma once
// Internal to the instruction reader (instruction.cpp, request_match.cpp, and priors.cpp for a
// state's words): the words of a request, as both sides of a gloss match read them. Sets of
// filler words, verb cues, words of degree and light verbs; stems; a closed compound's parts;
// which verbs are too general to name an act; a verb's kin (WordNet synonyms and first hypernym).

#include <set>
#include <string>
#include <vector>

namespace ussnav::request {

// Words that name nothing to look for ("a", "want", "somewhere", "i'm", ...).
const std::set<std::string>& fillers();
// Words after which a verb stands: "to print", "I wash", "can eat", "please watch", "let's eat".
const std::set<std::string>& verbCues();
// Words of degree between a state and who is in it: "I'm SO tired", "be VERY hot".
const std::set<std::string>& degreeWords();
// Verbs that take their meaning from the act after them: "take a bath", "have a nap".
const std::set<std::string>& lightVerbs();
// Stems of a text's words, filler words dropped.
std::set<std::string> stems(const std::string& text);
// A closed compound's parts, when both are WordNet nouns of four letters or more: a bookshelf
// is named for books and a coatrack for coats ("carpet" and "cupboard" stay whole).
std::vector<std::string> compoundParts(const std::string& word);
// Verbs too general to stand for another act: "eat" is to "take in", "relax" to "turn".
bool generalVerb(const std::string& w);
// The verb a stem stands for: the request keeps stems ("stor" for "store", "sit" for "sitting").
std::string verbOfStem(const std::string& stem);
// Stems of the single-word verbs that name a verb's act (wordnet::verbKin), general ones dropped.
std::set<std::string> kinVerbStems(const std::string& verb);

}  // namespace ussnav::request
