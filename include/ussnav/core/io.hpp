#pragma once
// File helpers. Every output is written atomically (temporary file in the same folder, then
// rename), so a crash or an error never leaves half a file behind.

#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace ussnav {

// Writes `bytes` to `path` atomically; creates parent folders. Throws InputError on failure.
void writeFileAtomic(const std::filesystem::path& path, const std::string& bytes);
// Pretty-printed JSON (indent 2), atomically.
void writeJsonAtomic(const std::filesystem::path& path, const nlohmann::json& j);
// Compact JSON text to embed in an HTML <script> block: every '<' written \u003c (it occurs only
// inside strings, where the escape means the same), so no text can end the block; invalid UTF-8
// becomes U+FFFD rather than an exception.
std::string jsonForScript(const nlohmann::json& j);
// Whole file as bytes; throws InputError(path, "", "cannot read ...") when missing.
std::string readFile(const std::filesystem::path& path);
// Parses a JSON file; a syntax error becomes InputError naming the file and byte offset.
nlohmann::json readJsonFile(const std::filesystem::path& path);

}  // namespace ussnav
