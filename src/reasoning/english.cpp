// English forms for the reasoners' sentences (see english.hpp).

#include "english.hpp"

#include <cctype>
#include <map>

namespace ussnav::english {

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool vowel(char c) { return std::string("aeiou").find(c) != std::string::npos; }

}  // namespace

std::string withArticle(const std::string& noun) {
  return (!noun.empty() && vowel(noun[0]) ? "an " : "a ") + noun;
}

std::string plural(const std::string& noun) {
  if (noun.empty()) return noun;
  static const std::map<std::string, std::string> irregular{
      {"person", "people"}, {"child", "children"}, {"man", "men"},   {"woman", "women"},
      {"foot", "feet"},     {"tooth", "teeth"},    {"mouse", "mice"}, {"fish", "fish"}};
  const size_t space = noun.rfind(' ');
  const std::string head = space == std::string::npos ? noun : noun.substr(space + 1);
  if (const auto it = irregular.find(head); it != irregular.end())
    return noun.substr(0, noun.size() - head.size()) + it->second;
  const std::string stem = noun.substr(0, noun.size() - 1);
  if (endsWith(noun, "s") || endsWith(noun, "x") || endsWith(noun, "z") || endsWith(noun, "ch") ||
      endsWith(noun, "sh"))
    return noun + "es";
  if (noun.size() >= 2 && noun.back() == 'y' && !vowel(noun[noun.size() - 2])) return stem + "ies";
  if (endsWith(noun, "fe")) return noun.substr(0, noun.size() - 2) + "ves";
  if (endsWith(noun, "lf")) return stem + "ves";
  return noun + "s";
}

std::string capitalised(std::string s) {
  if (!s.empty()) s[0] = char(std::toupper(static_cast<unsigned char>(s[0])));
  return s;
}

std::string counted(int n, const std::string& noun) {
  return std::to_string(n) + " " + (n == 1 ? noun : plural(noun));
}

}  // namespace ussnav::english
