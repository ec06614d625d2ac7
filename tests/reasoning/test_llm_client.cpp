// LlmClient against the loopback FakeLlmServer: request shape, status classification, retries,
// Retry-After, timeouts, unreachable servers and base_url validation.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "support/fake_llm_server.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/reasoning/llm_client.hpp"

namespace ussnav {
namespace {

using test::FakeLlmServer;
using B = FakeLlmServer::Behaviour;

// Fast settings: short timeout and backoff keep the whole suite well under 2 s.
LlmConfig fastConfig(const std::string& base_url) {
  LlmConfig c;
  c.base_url = base_url;
  c.model = "test-model";
  c.api_key_env = "USSNAV_TEST_LLM_KEY_UNSET_" + std::to_string(::getpid());
  c.timeout_s = 0.2;
  c.retries = 2;
  c.backoff_s = 0.01;
  c.max_tokens = 77;
  c.temperature = 0.25;
  return c;
}

TEST(LlmClient, GoodAnswerSendsCompleteRequest) {
  FakeLlmServer srv;
  srv.push(B::content(R"({"region":"kitchen"})"));
  LlmConfig cfg = fastConfig(srv.baseUrl());
  cfg.api_key_env = "USSNAV_TEST_LLM_KEY_SET_" + std::to_string(::getpid());
  ASSERT_EQ(::setenv(cfg.api_key_env.c_str(), "sk-secret", 1), 0);
  const LlmReply r = LlmClient(cfg).chat("you are a planner", "where is the fridge?");
  ::unsetenv(cfg.api_key_env.c_str());

  EXPECT_EQ(r.status, LlmStatus::Ok) << r.error;
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.content, R"({"region":"kitchen"})");
  EXPECT_EQ(r.attempts, 1);
  EXPECT_EQ(r.http_status, 200);
  EXPECT_TRUE(r.error.empty());
  EXPECT_GT(r.latency_ms, 0.0);

  const auto reqs = srv.requests();
  ASSERT_EQ(reqs.size(), 1u);
  EXPECT_EQ(reqs[0].path, "/v1/chat/completions");
  EXPECT_EQ(reqs[0].authorization, "Bearer sk-secret");
  const auto j = nlohmann::json::parse(reqs[0].body);
  EXPECT_EQ(j.at("model"), "test-model");
  ASSERT_EQ(j.at("messages").size(), 2u);
  EXPECT_EQ(j["messages"][0].at("role"), "system");
  EXPECT_EQ(j["messages"][0].at("content"), "you are a planner");
  EXPECT_EQ(j["messages"][1].at("role"), "user");
  EXPECT_EQ(j["messages"][1].at("content"), "where is the fridge?");
  EXPECT_DOUBLE_EQ(j.at("temperature").get<double>(), 0.25);
  EXPECT_EQ(j.at("max_tokens"), 77);
  EXPECT_EQ(j.at("response_format").at("type"), "json_object");
}

TEST(LlmClient, PlainModeWithoutKeyOmitsResponseFormatAndAuthorization) {
  FakeLlmServer srv;
  srv.push(B::content("plain text"));
  LlmConfig cfg = fastConfig(srv.baseUrl() + "/");  // a trailing slash is tolerated
  cfg.json_mode = false;
  const LlmReply r = LlmClient(cfg).chat("s", "u");
  EXPECT_EQ(r.status, LlmStatus::Ok) << r.error;
  EXPECT_EQ(r.content, "plain text");
  const auto reqs = srv.requests();
  ASSERT_EQ(reqs.size(), 1u);
  EXPECT_EQ(reqs[0].path, "/v1/chat/completions");
  EXPECT_EQ(reqs[0].authorization, "");
  EXPECT_FALSE(nlohmann::json::parse(reqs[0].body).contains("response_format"));
}

TEST(LlmClient, BaseUrlWithoutPrefixPostsAtRoot) {
  FakeLlmServer srv;
  const LlmReply r = LlmClient(fastConfig("http://127.0.0.1:" + std::to_string(srv.port()))).chat("s", "u");
  EXPECT_EQ(r.status, LlmStatus::Ok) << r.error;
  EXPECT_EQ(r.content, "ok");  // the server's default behaviour
  ASSERT_EQ(srv.requestCount(), 1u);
  EXPECT_EQ(srv.requests()[0].path, "/chat/completions");
}

TEST(LlmClient, MalformedBodiesAreBadResponseWithoutRetry) {
  for (const std::string& body : {std::string("not json {"), std::string(R"({"choices":[]})"),
                                 std::string(R"({"choices":[{"message":{"content":null}}]})"),
                                 std::string(R"([1,2,3])")}) {
    FakeLlmServer srv;
    srv.push(B::raw(body));
    const LlmReply r = LlmClient(fastConfig(srv.baseUrl())).chat("s", "u");
    EXPECT_EQ(r.status, LlmStatus::BadResponse) << body;
    EXPECT_EQ(r.attempts, 1) << body;
    EXPECT_EQ(r.http_status, 200) << body;
    EXPECT_EQ(srv.requestCount(), 1u) << body;
    EXPECT_TRUE(r.content.empty()) << body;
    EXPECT_FALSE(r.error.empty()) << body;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << body;
  }
}

TEST(LlmClient, ServerErrorThenGoodIsRetried) {
  FakeLlmServer srv;
  srv.push(B::httpStatus(500));
  srv.push(B::content("second time lucky"));
  const LlmReply r = LlmClient(fastConfig(srv.baseUrl())).chat("s", "u");
  EXPECT_EQ(r.status, LlmStatus::Ok) << r.error;
  EXPECT_EQ(r.content, "second time lucky");
  EXPECT_EQ(r.attempts, 2);
  EXPECT_EQ(r.http_status, 200);
  EXPECT_EQ(srv.requestCount(), 2u);
}

TEST(LlmClient, RateLimitHonoursRetryAfter) {
  FakeLlmServer srv;
  srv.push(B::httpStatus(429, "1"));
  srv.push(B::content("after the wait"));
  const LlmReply r = LlmClient(fastConfig(srv.baseUrl())).chat("s", "u");
  EXPECT_EQ(r.status, LlmStatus::Ok) << r.error;
  EXPECT_EQ(r.content, "after the wait");
  EXPECT_EQ(r.attempts, 2);
  EXPECT_EQ(srv.requestCount(), 2u);
  EXPECT_GE(r.latency_ms, 950.0);  // Retry-After: 1 s beats the 10 ms backoff
  EXPECT_LT(r.latency_ms, 5000.0);
}

TEST(LlmClient, PersistentServerErrorGivesUpAfterRetries) {
  FakeLlmServer srv;
  srv.setDefault(B::httpStatus(503, "", "overloaded\nplease wait"));
  LlmConfig cfg = fastConfig(srv.baseUrl());
  cfg.retries = 3;
  const LlmReply r = LlmClient(cfg).chat("s", "u");
  EXPECT_EQ(r.status, LlmStatus::HttpError);
  EXPECT_EQ(r.attempts, cfg.retries + 1);
  EXPECT_EQ(r.http_status, 503);
  EXPECT_EQ(srv.requestCount(), static_cast<size_t>(cfg.retries + 1));
  EXPECT_NE(r.error.find("503"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("overloaded please wait"), std::string::npos) << r.error;
  // Backoff 10, 20, 40 ms between the four attempts.
  EXPECT_GE(r.latency_ms, 70.0);
}

TEST(LlmClient, ClientErrorIsNotRetried) {
  FakeLlmServer srv;
  srv.setDefault(B::httpStatus(401, "", R"({"error":"bad key"})"));
  const LlmReply r = LlmClient(fastConfig(srv.baseUrl())).chat("s", "u");
  EXPECT_EQ(r.status, LlmStatus::HttpError);
  EXPECT_EQ(r.attempts, 1);
  EXPECT_EQ(r.http_status, 401);
  EXPECT_EQ(srv.requestCount(), 1u);
  EXPECT_NE(r.error.find("bad key"), std::string::npos) << r.error;
}

TEST(LlmClient, HangingServerTimesOut) {
  FakeLlmServer srv;
  srv.setDefault(B::hang(10.0, "too late"));
  LlmConfig cfg = fastConfig(srv.baseUrl());
  cfg.retries = 1;
  const LlmReply r = LlmClient(cfg).chat("s", "u");
  EXPECT_EQ(r.status, LlmStatus::Timeout) << r.error;
  EXPECT_EQ(r.attempts, 2);
  EXPECT_EQ(r.http_status, 0);
  EXPECT_TRUE(r.content.empty());
  EXPECT_GE(r.latency_ms, 2 * 0.2 * 1e3 * 0.9);
  EXPECT_LT(r.latency_ms, 2000.0);
  EXPECT_FALSE(r.error.empty());
}  // the destructor wakes both hanging handlers

TEST(LlmClient, TimeoutThenGoodRecovers) {
  FakeLlmServer srv;
  srv.push(B::hang(10.0));
  srv.push(B::content("fast now"));
  const LlmReply r = LlmClient(fastConfig(srv.baseUrl())).chat("s", "u");
  EXPECT_EQ(r.status, LlmStatus::Ok) << r.error;
  EXPECT_EQ(r.content, "fast now");
  EXPECT_EQ(r.attempts, 2);
}

TEST(LlmClient, ClosedPortIsANetworkFaultNotAnException) {
  std::string url;
  {
    FakeLlmServer srv;
    url = srv.baseUrl();
  }  // stopped: nothing listens on that port any more
  LlmConfig cfg = fastConfig(url);
  cfg.retries = 1;
  std::optional<LlmReply> r;
  EXPECT_NO_THROW(r = LlmClient(cfg).chat("s", "u"));
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(r->status == LlmStatus::NetworkError || r->status == LlmStatus::Timeout) << toString(r->status);
  EXPECT_EQ(r->attempts, 2);
  EXPECT_EQ(r->http_status, 0);
  EXPECT_FALSE(r->error.empty());
}

TEST(LlmClient, HttpsToAPlainServerIsANetworkFault) {
  // With OpenSSL the TLS handshake fails; without it the client refuses https up front.
  FakeLlmServer srv;
  LlmConfig cfg = fastConfig("https://127.0.0.1:" + std::to_string(srv.port()) + "/v1");
  cfg.retries = 0;
  std::optional<LlmReply> r;
  EXPECT_NO_THROW(r = LlmClient(cfg).chat("s", "u"));
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->status, LlmStatus::NetworkError) << r->error;
  EXPECT_FALSE(r->error.empty());
}

TEST(LlmClient, BadBaseUrlThrowsInputError) {
  for (const char* url : {"ftp://example.com/v1", "127.0.0.1:8000/v1", "http://", "", "http:///v1",
                          "HTTP//x"}) {
    try {
      LlmClient c(fastConfig(url));
      ADD_FAILURE() << "no exception for '" << url << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "reasoning.llm") << url;
      EXPECT_EQ(e.field(), "base_url") << url;
    }
  }
  EXPECT_NO_THROW(LlmClient(fastConfig("https://api.example.com/v1")));
  EXPECT_NO_THROW(LlmClient(fastConfig("http://localhost")));
}

TEST(LlmClient, StatusNames) {
  EXPECT_STREQ(toString(LlmStatus::Ok), "ok");
  EXPECT_STREQ(toString(LlmStatus::Timeout), "timeout");
  EXPECT_STREQ(toString(LlmStatus::HttpError), "http_error");
  EXPECT_STREQ(toString(LlmStatus::NetworkError), "network_error");
  EXPECT_STREQ(toString(LlmStatus::BadResponse), "bad_response");
}

}  // namespace
}  // namespace ussnav
