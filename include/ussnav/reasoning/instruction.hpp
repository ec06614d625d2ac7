#pragma once
// Free-text instructions -> what would satisfy them (paper Sec. V-B, "zero-shot"): "bed",
// "find a bed", "somewhere to sleep", "the sofa in the living room", "I want to attend a
// meeting". Offline, from WordNet and the commonsense priors, no model:
//  1. a room phrase naming a room type or alias of room_types.tsv ("in the living room") becomes
//     the room constraint; a particle after a verb WordNet knows with it goes ("lie down",
//     "work out" -> "to exercise"), and a word that is only an adjective whose definition names
//     an act becomes it ("hungry": "a desire to eat food" -> "to eat");
//  2. a named object: the longest n-gram of words said together ("water the plants" names no
//     water plant) that WordNet knows as a physical thing (artifact, plant, object, food) or
//     that matches a category of the priors by text cosine -> targets;
//     a verb ("watch" tv, "to use" the toilet) starts none unless the n-gram is a WordNet noun,
//     and with a verb present step 3 may name a category that fits verb and object better
//     ("wash clothes" -> washing machine); asked for a place ("somewhere to hang my coat") the
//     object is only one candidate of step 3 and the request is judged (a coat rack serves it);
//     an object that names no category ("cook dinner", "clean the floor") leaves the search to
//     what does the act (a pan; a vacuum cleaner), and only that serves (act_required), unless
//     its own gloss uses the act as a verb ("play the piano": a piano "is played"). A word
//     names a thing only when that is one of its first two WordNet senses ("a rest" is none).
//     A light verb and an act ("take a bath", "I need a nap") ask for what the act needs: the
//     act's WordNet gloss is read as the request; a meal that is a verb too, its verb's ("have
//     breakfast": to "eat an early morning meal");
//  3. otherwise a functional request: the content words (stemmed, filler words dropped) are
//     looked up in each candidate category's name, synonyms and WordNet gloss ("bed: a piece of
//     furniture that provides a place to sleep": 2 for a name, 1.5 for a purpose "to / for W",
//     1 for a mention or for the act in other words, wordnet::verbKin, or for a purpose whose
//     verb hypernyms hold the act: to sleep is to rest and to lie; 0.9 of it where only the
//     hypernym's gloss answers, 0.8 where only a kind of it is for the act: a sink may be a
//     washbasin, "where you can wash your hands"); nouns WordNet derives from the act are
//     candidates too ("print" -> printer; the act's own word when a thing is what it first
//     means: "mop" -> mop, not "print" -> print), looked for when no category answers by name or
//     purpose; the best-scoring categories become the targets (among equals, one named for the
//     act, then furniture, fixtures and appliances: a dining table before a fork), the
//     best-scoring room type a hint;
//  4. nothing recognised: the content words themselves are the target (an unknown label can
//     still be matched by the text encoder).
// Candidate categories: the priors' tables plus `extra_vocabulary` (e.g. labels in a scene graph).

#include <string>
#include <vector>

#include "ussnav/reasoning/priors.hpp"

namespace ussnav {

struct Instruction {
  std::string text;                  // as given
  std::vector<std::string> targets;  // object categories that satisfy it, best first
  std::string room;                  // required room type, "" = anywhere
  std::string room_hint;             // room type a functional request points at, "" = none
  std::string how;                   // named | functional | literal | room_only
  // A functional request's stemmed content words (of them, those standing as verbs) and the
  // targets' score: what labels the vocabulary did not hold are judged by (servesRequest).
  std::vector<std::string> request, request_verbs;
  double score = 0.0;
  // The request names what the act is on ("store clothes"): a label serves only if it answers that.
  bool object_named = false;
  // What the act is on is no category ("cook dinner", "clean the floor") or is the requester's
  // body ("wash my hands"): a label serves only if it answers the act (a pan, a vacuum cleaner;
  // not a floor lamp, nor a "hand-held" hair dryer).
  bool act_required = false;
};

// Throws InputError (file "goal") on an empty or all-filler instruction.
Instruction interpretInstruction(const std::string& text, const CommonsensePriors& priors,
                                 const std::vector<std::string>& extra_vocabulary = {});

// Step 3's score of a label against a functional request (0 for other kinds).
double requestScore(const Instruction& instruction, const std::string& label);
// Whether an object labelled `label` satisfies a functional request as well as its best targets
// do: a stove, seen, serves "somewhere to cook" though the priors' vocabulary offered a pan.
// False for named, literal and room-only instructions (their targets are matched by the text
// encoder).
bool servesRequest(const Instruction& instruction, const std::string& label);

// Lower-cased words of a text, punctuation dropped.
std::vector<std::string> instructionWords(const std::string& text);
// Crude suffix stemmer shared by both sides of a gloss match ("sleeping" -> "sleep").
std::string stemWord(const std::string& w);

}  // namespace ussnav
