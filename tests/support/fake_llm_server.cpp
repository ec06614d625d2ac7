// FakeLlmServer: cpp-httplib server on a loopback port driven by a queue of behaviours.
#include "support/fake_llm_server.hpp"

#include <httplib.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

namespace ussnav::test {

using Behaviour = FakeLlmServer::Behaviour;

Behaviour Behaviour::content(std::string assistant_content) {
  Behaviour b;
  b.kind = Kind::Content;
  b.text = std::move(assistant_content);
  return b;
}

Behaviour Behaviour::raw(std::string body) {
  Behaviour b;
  b.kind = Kind::RawBody;
  b.text = std::move(body);
  return b;
}

Behaviour Behaviour::httpStatus(int status, std::string retry_after, std::string body) {
  Behaviour b;
  b.kind = Kind::Status;
  b.status = status;
  b.retry_after = std::move(retry_after);
  b.text = std::move(body);
  return b;
}

Behaviour Behaviour::hang(double seconds, std::string assistant_content) {
  Behaviour b;
  b.kind = Kind::Hang;
  b.hang_s = seconds;
  b.text = std::move(assistant_content);
  return b;
}

namespace {

std::string completionJson(const std::string& content) {
  const nlohmann::json j = {
      {"id", "chatcmpl-fake"},
      {"object", "chat.completion"},
      {"created", 0},
      {"model", "fake"},
      {"choices", nlohmann::json::array({{{"index", 0},
                                          {"message", {{"role", "assistant"}, {"content", content}}},
                                          {"finish_reason", "stop"}}})},
      {"usage", {{"prompt_tokens", 0}, {"completion_tokens", 0}, {"total_tokens", 0}}}};
  return j.dump();
}

}  // namespace

struct FakeLlmServer::Impl {
  httplib::Server svr;
  std::thread thread;
  int port = -1;
  mutable std::mutex mu;
  std::condition_variable cv;  // wakes hanging handlers on stop()
  bool stopping = false;
  std::deque<Behaviour> script;
  Behaviour fallback = Behaviour::content("ok");
  std::vector<Request> received;

  void handle(const httplib::Request& req, httplib::Response& res) {
    Behaviour b;
    {
      std::unique_lock lock(mu);
      received.push_back({req.path, req.body, req.get_header_value("Authorization")});
      if (!script.empty()) {
        b = std::move(script.front());
        script.pop_front();
      } else {
        b = fallback;
      }
      if (b.kind == Behaviour::Kind::Hang)
        cv.wait_for(lock, std::chrono::duration<double>(b.hang_s), [this] { return stopping; });
    }
    switch (b.kind) {
      case Behaviour::Kind::Content:
      case Behaviour::Kind::Hang:
        res.set_content(completionJson(b.text), "application/json");
        break;
      case Behaviour::Kind::RawBody:
        res.set_content(b.text, "application/json");
        break;
      case Behaviour::Kind::Status:
        res.status = b.status;
        if (!b.retry_after.empty()) res.set_header("Retry-After", b.retry_after);
        res.set_content(b.text, "application/json");
        break;
    }
  }
};

FakeLlmServer::FakeLlmServer() : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.svr.set_keep_alive_max_count(1);
  im.svr.Post(".*", [&im](const httplib::Request& req, httplib::Response& res) { im.handle(req, res); });
  im.port = im.svr.bind_to_any_port("127.0.0.1");
  if (im.port <= 0) throw std::runtime_error("FakeLlmServer: cannot bind a port on 127.0.0.1");
  im.thread = std::thread([&im] { im.svr.listen_after_bind(); });
  // stop() is a no-op before the server runs, so wait for it to be running.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!im.svr.is_running() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  if (!im.svr.is_running()) {
    stop();
    throw std::runtime_error("FakeLlmServer: server did not start");
  }
}

FakeLlmServer::~FakeLlmServer() { stop(); }

void FakeLlmServer::stop() {
  {
    std::lock_guard lock(impl_->mu);
    impl_->stopping = true;
  }
  impl_->cv.notify_all();
  impl_->svr.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

void FakeLlmServer::push(Behaviour b) {
  std::lock_guard lock(impl_->mu);
  impl_->script.push_back(std::move(b));
}

void FakeLlmServer::setDefault(Behaviour b) {
  std::lock_guard lock(impl_->mu);
  impl_->fallback = std::move(b);
}

std::string FakeLlmServer::baseUrl() const {
  return "http://127.0.0.1:" + std::to_string(impl_->port) + "/v1";
}

int FakeLlmServer::port() const { return impl_->port; }

std::vector<FakeLlmServer::Request> FakeLlmServer::requests() const {
  std::lock_guard lock(impl_->mu);
  return impl_->received;
}

size_t FakeLlmServer::requestCount() const {
  std::lock_guard lock(impl_->mu);
  return impl_->received.size();
}

}  // namespace ussnav::test
