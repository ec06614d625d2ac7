#pragma once
// Commonsense priors of the built-in reasoner (paper Sec. V-B stand-in for the LLM's world
// knowledge), read from independent published tables copied into data/priors/ (its README
// credits them; none comes from this project's world generator):
//  - ProcTHOR's human-annotated placement weights (0 never / 1 possible / 2 likely) of 109 object
//    types in kitchens, living rooms, bedrooms and bathrooms: likelihoods 0.03 / 0.35 / 1;
//  - SG-Nav's object-room co-occurrence scores (21 MP3D goal categories x 9 room types), read as
//    log-likelihoods: exp(score);
//  - MP3D's mpcat40 table (MIT): the NYU40 classes and raw labels each SG-Nav category covers,
//    as aliases (tv_monitor: television; chest_of_drawers: dresser, night stand);
//  - MP3D's category_mapping (MIT): 1,659 raw labels annotators gave objects in 90 scanned houses,
//    each filed under an mpcat40 category ("nightstand" -> chest_of_drawers, "monitor" ->
//    tv_monitor), consulted when the label names no category itself;
//  - room_types.tsv (the room types, aliases, which table column means each),
//    room_adjacency.tsv (which room types open onto each other) and states.tsv (how one feels,
//    and what one then asks for: tired -> "to sleep"), written for this project.
// P(room | object label): the label is matched to the categories' names and aliases (spaces
// aside: "armchair" is ArmChair), else through the MP3D raw-label table, else through a WordNet
// synonym ("tv" -> tv_monitor by its alias television), else by the text encoder to every
// category within match_cosine ("couch" -> Sofa), failing that to the nearest within cosine 0.7 at
// half weight ("refrigerator" -> Fridge). Two more kinds of row come from the words themselves:
// a matched label's accessories, the compounds one word longer that it (or a WordNet synonym)
// modifies ("tv" -> TVStand, "toilet" -> ToiletPaper), and a room the label or its nearest
// WordNet hypernym names ("office chair", "microwave" = kitchen appliance, "filing cabinet" =
// office furniture), a row all on that room, which stands in for the loose text match. Each
// matching row is normalised over the rooms its table covers, and the rows are averaged. Rows
// that say nothing (all zero) are skipped. A label matching nothing has no prior (empty vector).
// Thread-safe for const use; roomsGivenObject() caches per label.

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ussnav/perception/text_encoder.hpp"

namespace ussnav {

struct RoomType {
  std::string name;                  // "living room"
  std::vector<std::string> aliases;  // "family room", ...
  std::string description;           // one line
};

class CommonsensePriors {
 public:
  // Reads dir/{room_types.tsv, room_adjacency.tsv, states.tsv, procthor_object_room_weights.tsv,
  // sgnav_object_room_cooccurrence.csv, mpcat40.tsv, mp3d_category_mapping.tsv}. Throws InputError
  // naming the file and line/field on a missing file or a malformed row.
  static std::shared_ptr<const CommonsensePriors> load(const std::filesystem::path& dir, std::shared_ptr<const TextEncoder> encoder,
                                                         double match_cosine = 0.85);
  // The repository's data/priors (next to configs/), or empty when not found.
  static std::filesystem::path defaultDir();

  const std::vector<RoomType>& rooms() const { return rooms_; }
  // Index of a room type by name or alias (case-insensitive, then by text cosine >= match_cosine);
  // -1 when none.
  int roomIndex(const std::string& name) const;
  // The room type a word names: a one-word name or alias ("office", "corridor"), else the first
  // word of a two-word one ("dining", "conference", "laundry"); -1 when none.
  int roomNamedBy(const std::string& word) const;
  // The room a label names in its own words or its nearest WordNet hypernym's: "office chair",
  // "kitchen counter", "microwave" (a kitchen appliance), "filing cabinet" (office furniture);
  // -1 when none.
  int roomCue(const std::string& label) const;
  // Whether WordNet knows the label by its head noun only, with a thing before it that is no
  // room, animal or furnishing ("shoe cabinet", "wine rack"; not "office chair", "dog bed",
  // "sofa bed"): a kind made for that thing, whose room the head's table row says only loosely.
  bool forAThing(const std::string& label) const;
  // P(room | an object with this label), size rooms(); empty when the label matches no category.
  std::vector<double> roomsGivenObject(const std::string& label) const;
  // Room adjacency prior in [0, 1] (listed pairs, else 0.1).
  double adjacency(int a, int b) const;
  // A state's row in states.tsv: of the word itself, else of the first of its two most frequent
  // WordNet adjective senses whose words or cluster head have one ("exhausted" -> tired, "drowsy"
  // -> asleep, "filthy" -> dirty), else, for an -ing or -ed word, of the adjective one of its
  // verb's first four senses is being ("starving": "be hungry"; "freezing": "be cold"). The row
  // holds what the state stands for said of the one asking ("to sleep"), and the act done to a
  // thing or a part of the body in it ("wash"; "" when the state calls for none: tired, hungry).
  // nullptr when the word has no row.
  struct StateRow {
    std::string request;
    std::string act;
  };
  const StateRow* stateFor(const std::string& word) const;
  // The tables' object categories as words ("ArmChair" -> "arm chair"), for instructions.
  const std::vector<std::string>& categories() const { return categories_; }
  const TextEncoder& encoder() const { return *encoder_; }
  std::shared_ptr<const TextEncoder> encoderPtr() const { return encoder_; }

 private:
  struct Row {
    std::string category;          // as words
    std::vector<std::string> names;  // category and its aliases (mpcat40), matched against labels
    std::vector<double> p;         // over rooms_, sums to 1
    // Per name: its head noun when it names a kind made for another thing (forAThing: "coffee
    // machine" -> "machine"), else "".
    std::vector<std::string> kind_heads;
  };
  std::vector<RoomType> rooms_;
  std::vector<std::vector<double>> adjacency_;
  std::vector<Row> rows_;
  std::vector<std::string> categories_;
  std::shared_ptr<const TextEncoder> encoder_;
  double match_cosine_ = 0.85;
  std::map<std::string, std::string> mp3d_;    // raw label (lower case) -> a row's category words
  std::map<std::string, StateRow> states_;  // state word (lower case) -> its row
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::vector<double>> cache_;
};

// "ArmChair" -> "arm chair", "tv_monitor" -> "tv monitor", "TVStand" -> "tv stand" (the words of
// wordnet::labelTokens joined by spaces).
std::string categoryWords(const std::string& name);

}  // namespace ussnav
