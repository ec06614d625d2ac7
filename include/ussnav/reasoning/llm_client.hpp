#pragma once
// A minimal OpenAI-compatible chat-completions client (POST {base_url}/chat/completions) for the
// `llm` reasoner. One call = one system + one user message; the reply's
// choices[0].message.content is returned as text (the caller parses and validates it).
// Faults are reported, never thrown: a timeout, HTTP 429 / 5xx and network errors are retried
// up to cfg.retries times with exponential backoff (429 honours a larger Retry-After); other
// HTTP errors and malformed bodies are not retried. http:// and https:// (when cpp-httplib was
// built with OpenSSL) base URLs are accepted; the API key comes from the environment variable
// cfg.api_key_env (sent as "Authorization: Bearer KEY" when set). Thread-safe: each call opens
// its own connection.

#include <string>

#include "ussnav/core/config.hpp"

namespace ussnav {

enum class LlmStatus {
  Ok,           // content holds the assistant's message
  Timeout,      // no (complete) answer within timeout_s, after all retries
  HttpError,    // a non-2xx status after all retries (http_status says which)
  NetworkError, // connection refused / reset, bad URL
  BadResponse,  // 2xx but the body is not a chat completion (no choices[0].message.content)
};
const char* toString(LlmStatus s);

struct LlmReply {
  LlmStatus status = LlmStatus::NetworkError;
  std::string content;      // the message text when Ok
  int http_status = 0;      // last HTTP status seen, 0 if none
  int attempts = 0;         // requests sent
  double latency_ms = 0.0;  // wall time of the whole call, retries and waits included
  std::string error;        // one line for logs when not Ok
  bool ok() const { return status == LlmStatus::Ok; }
};

class LlmClient {
 public:
  // Throws InputError (file "reasoning.llm", field base_url) on a URL that is not http(s)://.
  explicit LlmClient(LlmConfig cfg);
  LlmReply chat(const std::string& system, const std::string& user) const;
  const LlmConfig& config() const { return cfg_; }

 private:
  LlmConfig cfg_;
  std::string scheme_host_port_, path_prefix_;
};

}  // namespace ussnav
