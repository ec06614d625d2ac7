// The few English forms the reasoners' sentences need (region descriptions, `ussnav ask`).
// A label is a lower-case noun phrase from the detector's vocabulary; its last word is the head.

#pragma once

#include <string>

namespace ussnav::english {

// "a chair", "an office chair": the first letter decides ("an hour", "a unit" are not handled).
std::string withArticle(const std::string& noun);

// The plural of a noun phrase's head: chair -> chairs, glass -> glasses, shelf -> shelves,
// knife -> knives, laundry -> laundries, toy -> toys, person -> people; "" stays "".
std::string plural(const std::string& noun);

// "Living room" for "living room".
std::string capitalised(std::string s);

// "1 chair", "3 chairs".
std::string counted(int n, const std::string& noun);

}  // namespace ussnav::english
