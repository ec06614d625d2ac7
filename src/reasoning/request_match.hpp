#pragma once
// Internal to the instruction reader (instruction.cpp): step 3's score of one name against a
// request's stemmed content words (instruction.hpp says what counts how much). A name's words,
// synonyms and glosses are read once and kept for the process.

#include <set>
#include <string>

namespace ussnav::request {

struct RequestMatch {
  double score = 0.0;
  bool verb = false;    // a verb of the request found (the act)
  bool object = false;  // a word of the request that is no verb found (what the act is on)
  bool purpose = false;  // a verb found in what the gloss says the thing is for, not in its name
  bool act_named = false;  // a verb found in its name: the thing is named for the act
  bool for_act = false;    // a verb found in its gloss as a verb ("a place TO SLEEP", "can SIT")
};

// Step 3's score of one name against the request's stemmed content words `want` (of them
// `verbs` stand as verbs): 2 per word in the name, its synonyms or a closed compound's parts
// (book-shelf), 1.5 per purpose ("a place TO SLEEP", "used FOR COOKING"), 1 per other mention,
// in the name's WordNet gloss, its nearest hypernym's gloss (a chair is "a seat", a seat
// "furniture that is designed for sitting on") and `extra_text`; an -ing word of the name adds
// its verb's gloss ("dining" table: to dine is to "eat dinner"). A verb of the
// request counts in a gloss only where the gloss uses it as a verb: a purpose, an -ing / -ed
// form, after "can" ("where several people can SIT"); a book is "a written work", not somewhere
// to work. Failing those, 1 where the gloss names the act in other words (wordnet::verbKin: a
// dresser is "for KEEPING clothes" and to store is to keep; a refrigerator is where food "can be
// STORED" for "keep food cold"; a wardrobe "provides STORAGE"). A name that answers both the act
// and what it is on gets 0.5 more ("store clothes": a dresser, not a clothes dryer).
// `object` false (room types, scored on our own descriptions, written as purposes): no
// hypernym, no verb glosses, no kin.
// Since session 42 also: the act's verb hypernyms and nouns as purposes (to sleep is to rest
// and to lie; a toilet is "for urination"), a thing WordNet derives from the act named for it
// (a vacuum CLEANER), a verb too general to name an act ("make") only in a name, and what only
// the hypernym's gloss answers at 0.9. Since session 43: what only a direct kind of it is for (a
// verb of the request in the kind's gloss, as a verb) at 0.8 (a sink may be a washbasin), and
// an -ing word's verb gloss answers the request's verbs as purposes, its other words as mentions.
// `kinds` false: without the kinds, for judging a label seen (a can may be a canister, "for
// storing dry foods", but a can seen is not known to be one; a microwave's hypernym, a kitchen
// appliance, may be a refrigerator, which says nothing of the microwave).
RequestMatch matchRequest(const std::set<std::string>& want, const std::set<std::string>& verbs,
                          const std::string& name, const std::string& extra_text, bool object, bool kinds = true);

}  // namespace ussnav::request
