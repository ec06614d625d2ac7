// OpenAI-compatible chat-completions client over cpp-httplib: builds the request, retries
// timeouts / 429 / 5xx / network errors with exponential backoff, and classifies every fault
// into an LlmReply (nothing escapes chat()).
// Note: Debian's libcpp-httplib is a compiled library built with OpenSSL; every translation
// unit including <httplib.h> must use its pkg-config Cflags (-DCPPHTTPLIB_OPENSSL_SUPPORT ...),
// otherwise httplib::Client's layout differs from the library's.
#include "ussnav/reasoning/llm_client.hpp"

#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <thread>

#include "ussnav/core/error.hpp"

namespace ussnav {

const char* toString(LlmStatus s) {
  switch (s) {
    case LlmStatus::Ok: return "ok";
    case LlmStatus::Timeout: return "timeout";
    case LlmStatus::HttpError: return "http_error";
    case LlmStatus::NetworkError: return "network_error";
    case LlmStatus::BadResponse: return "bad_response";
  }
  return "unknown";
}

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// At most `n` characters of `s` on one line (for log messages).
std::string excerpt(const std::string& s, size_t n = 200) {
  std::string out = s.substr(0, n);
  std::replace_if(out.begin(), out.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
  if (s.size() > n) out += "...";
  return out;
}

// Outcome of one HTTP attempt.
struct Attempt {
  LlmStatus status = LlmStatus::NetworkError;
  bool retryable = false;
  double retry_after_s = 0.0;  // from a 429's Retry-After header, 0 if none
};

// choices[0].message.content as a string, or false.
bool extractContent(const std::string& body, std::string& content) {
  const auto j = nlohmann::json::parse(body, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) return false;
  const auto choices = j.find("choices");
  if (choices == j.end() || !choices->is_array() || choices->empty()) return false;
  const auto& c0 = (*choices)[0];
  if (!c0.is_object()) return false;
  const auto msg = c0.find("message");
  if (msg == c0.end() || !msg->is_object()) return false;
  const auto text = msg->find("content");
  if (text == msg->end() || !text->is_string()) return false;
  content = text->get<std::string>();
  return true;
}

}  // namespace

LlmClient::LlmClient(LlmConfig cfg) : cfg_(std::move(cfg)) {
  const std::string& url = cfg_.base_url;
  size_t scheme_end = 0;
  if (url.rfind("http://", 0) == 0) scheme_end = 7;
  else if (url.rfind("https://", 0) == 0) scheme_end = 8;
  const size_t slash = scheme_end ? url.find('/', scheme_end) : std::string::npos;
  const std::string host_port = scheme_end ? url.substr(scheme_end, slash - scheme_end) : "";
  if (host_port.empty() || host_port.front() == ':')
    throw InputError("reasoning.llm", "base_url",
                     "expected http://host[:port][/prefix] or https://..., got '" + url + "'");
  scheme_host_port_ = url.substr(0, scheme_end) + host_port;
  path_prefix_ = slash == std::string::npos ? "" : url.substr(slash);
  while (!path_prefix_.empty() && path_prefix_.back() == '/') path_prefix_.pop_back();
}

LlmReply LlmClient::chat(const std::string& system, const std::string& user) const {
  const auto t0 = Clock::now();
  LlmReply reply;
  try {
#ifndef CPPHTTPLIB_OPENSSL_SUPPORT
    if (scheme_host_port_.rfind("https://", 0) == 0) {
      reply.status = LlmStatus::NetworkError;
      reply.error = "https base_url '" + cfg_.base_url +
                    "' needs cpp-httplib built with OpenSSL (CPPHTTPLIB_OPENSSL_SUPPORT); use http://";
      reply.latency_ms = secondsSince(t0) * 1e3;
      return reply;
    }
#endif
    nlohmann::json body = {
        {"model", cfg_.model},
        {"messages", nlohmann::json::array({{{"role", "system"}, {"content", system}},
                                            {{"role", "user"}, {"content", user}}})},
        {"temperature", cfg_.temperature},
        {"max_tokens", cfg_.max_tokens}};
    if (cfg_.json_mode) body["response_format"] = {{"type", "json_object"}};
    const std::string payload = body.dump();
    const std::string path = path_prefix_ + "/chat/completions";

    httplib::Headers headers;
    if (const char* key = std::getenv(cfg_.api_key_env.c_str()); key && *key)
      headers.emplace("Authorization", std::string("Bearer ") + key);

    const double tmo = std::max(cfg_.timeout_s, 0.001);
    const auto sec = static_cast<time_t>(tmo);
    const auto usec = static_cast<time_t>(std::lround((tmo - static_cast<double>(sec)) * 1e6));

    for (int k = 0;; ++k) {
      Attempt at;
      const auto ta = Clock::now();
      {
        httplib::Client cli(scheme_host_port_);
        cli.set_connection_timeout(sec, usec);
        cli.set_read_timeout(sec, usec);
        cli.set_write_timeout(sec, usec);
        ++reply.attempts;
        const httplib::Result res = cli.Post(path, headers, payload, "application/json");
        if (!res) {
          const httplib::Error err = res.error();
          // A read error at the deadline is a timeout; an early one is a dropped connection.
          const bool timed_out = err == httplib::Error::ConnectionTimeout ||
                                 (err == httplib::Error::Read && secondsSince(ta) >= 0.9 * tmo);
          at.status = timed_out ? LlmStatus::Timeout : LlmStatus::NetworkError;
          at.retryable = true;
          reply.error = std::string(timed_out ? "timeout" : "network error") + " (" +
                        httplib::to_string(err) + ") after " +
                        std::to_string(static_cast<int>(secondsSince(ta) * 1e3)) + " ms on POST " +
                        scheme_host_port_ + path;
        } else {
          const int code = res->status;
          reply.http_status = code;
          if (code >= 200 && code < 300) {
            if (extractContent(res->body, reply.content)) {
              reply.status = LlmStatus::Ok;
              reply.error.clear();
              break;
            }
            at.status = LlmStatus::BadResponse;
            reply.error = "HTTP " + std::to_string(code) +
                          " but no choices[0].message.content string in body: " + excerpt(res->body);
          } else {
            at.status = LlmStatus::HttpError;
            at.retryable = code == 429 || code >= 500;
            reply.error = "HTTP " + std::to_string(code) + ": " + excerpt(res->body);
            if (code == 429 && res->has_header("Retry-After")) {
              const std::string ra = res->get_header_value("Retry-After");
              char* end = nullptr;
              const double v = std::strtod(ra.c_str(), &end);
              if (end != ra.c_str() && *end == '\0' && std::isfinite(v) && v > 0.0)
                at.retry_after_s = std::min(v, 30.0);
            }
          }
        }
      }
      reply.status = at.status;
      if (!at.retryable || k >= cfg_.retries) break;
      const double wait = std::max(cfg_.backoff_s * std::ldexp(1.0, k), at.retry_after_s);
      std::this_thread::sleep_for(std::chrono::duration<double>(wait));
    }
  } catch (const std::exception& e) {
    reply.status = LlmStatus::NetworkError;
    reply.error = std::string("exception: ") + excerpt(e.what());
  } catch (...) {
    reply.status = LlmStatus::NetworkError;
    reply.error = "unknown exception";
  }
  if (reply.status != LlmStatus::Ok) reply.content.clear();
  reply.latency_ms = secondsSince(t0) * 1e3;
  return reply;
}

}  // namespace ussnav
