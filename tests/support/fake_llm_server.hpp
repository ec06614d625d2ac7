#pragma once
// A scripted OpenAI-compatible chat-completions server on 127.0.0.1 (random port) for tests of
// the LLM client: each request pops the next behaviour (a good answer, a raw body, an HTTP
// status, or a hang) and is recorded. Runs on its own thread; the destructor stops it, waking
// any handler still hanging.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace ussnav::test {

class FakeLlmServer {
 public:
  struct Behaviour {
    enum class Kind { Content, RawBody, Status, Hang };
    Kind kind = Kind::Content;
    std::string text;         // Content/Hang: assistant content; RawBody/Status: response body
    int status = 200;         // Status: the HTTP status
    std::string retry_after;  // Status: Retry-After header value when non-empty
    double hang_s = 0.0;      // Hang: seconds to wait before answering with `text`

    static Behaviour content(std::string assistant_content);
    static Behaviour raw(std::string body);
    static Behaviour httpStatus(int status, std::string retry_after = "",
                                std::string body = R"({"error":{"message":"scripted failure"}})");
    static Behaviour hang(double seconds, std::string assistant_content = "{}");
  };
  struct Request {
    std::string path, body, authorization;  // authorization: the header's value, "" if absent
  };

  FakeLlmServer();  // listening when it returns; throws std::runtime_error if it cannot bind
  ~FakeLlmServer();
  FakeLlmServer(const FakeLlmServer&) = delete;
  FakeLlmServer& operator=(const FakeLlmServer&) = delete;

  void push(Behaviour b);        // appended to the script
  void setDefault(Behaviour b);  // used once the script is empty (initially content("ok"))
  std::string baseUrl() const;   // "http://127.0.0.1:PORT/v1"
  int port() const;
  std::vector<Request> requests() const;  // every request received so far, in order
  size_t requestCount() const;
  void stop();  // idempotent; wakes hanging handlers

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ussnav::test
