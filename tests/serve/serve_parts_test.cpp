// The server's plain parts: targets, routes, the web root, key reduction.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "gestura/app/error.hpp"
#include "gestura/serve/clip_glb.hpp"
#include "gestura/serve/router.hpp"
#include "gestura/serve/static_files.hpp"
#include "gestura/serve/url.hpp"

namespace gestura::serve {
namespace {

TEST(ServeUrl, DecodesPathAndQuery) {
  const Target t = parse_target("/api/lexicon/HELLO%20WORLD?q=caf%C3%A9+au+lait&prefix=1&empty");
  EXPECT_EQ(t.path, "/api/lexicon/HELLO WORLD");
  EXPECT_EQ(t.query.at("q"), "café au lait");
  EXPECT_EQ(t.query.at("prefix"), "1");
  EXPECT_EQ(t.query.at("empty"), "");
  EXPECT_EQ(percent_decode("a+b", false), "a+b");
}

TEST(ServeUrl, RefusesBrokenEscapesNulAndBadUtf8) {
  for (const char* bad : {"/a%2", "/a%zz", "/a%00b", "/%C3%28", "/%ED%A0%80"}) {
    try {
      parse_target(bad);
      ADD_FAILURE() << bad;
    } catch (const app::AppError& e) {
      EXPECT_EQ(e.category(), app::ErrorCategory::usage) << bad;
      EXPECT_EQ(e.place().field, "url");
    }
  }
  EXPECT_TRUE(valid_utf8("naïve ✋ 🤟"));
  EXPECT_FALSE(valid_utf8("\xF0\x9F\xA4"));
  EXPECT_EQ(percent_encode("a b/é"), "a%20b%2F%C3%A9");
}

TEST(ServeRouter, MatchesPatternsAndTellsAllowedMethods) {
  Router router;
  int hit = 0;
  router.add("GET", "/api/jobs/{id}", "job", [&](ApiRequest&, const app::RunContext&) { hit = 1; return ApiResponse{}; });
  router.add("DELETE", "/api/jobs/{id}", "cancel", [&](ApiRequest&, const app::RunContext&) { hit = 2; return ApiResponse{}; });
  router.add("GET", "/*", "static", [&](ApiRequest&, const app::RunContext&) { hit = 3; return ApiResponse{}; });
  ApiRequest r{.method = "GET", .path = "/api/jobs/abc"};
  Router::Match m = router.match(r);
  ASSERT_TRUE(m.handler);
  EXPECT_EQ(m.name, "job");
  EXPECT_EQ(r.params.at("id"), "abc");
  r = ApiRequest{.method = "POST", .path = "/api/jobs/abc"};
  m = router.match(r);
  EXPECT_FALSE(m.handler);
  EXPECT_EQ(m.status, 405);
  EXPECT_EQ(m.allowed, "GET, DELETE");
  r = ApiRequest{.method = "HEAD", .path = "/index.html"};
  EXPECT_EQ(router.match(r).name, "static");
}

TEST(ServeStatic, ResolvesInsideTheRootOnly) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("gestura-static-" + std::to_string(::getpid()));
  fs::create_directories(root / "web" / "js");
  std::ofstream(root / "web" / "index.html") << "x";
  std::ofstream(root / "web" / "js" / "app.js") << "x";
  std::ofstream(root / "outside.txt") << "x";
  const fs::path web = fs::canonical(root / "web");
  EXPECT_EQ(resolve_static(web, "/"), web / "index.html");
  EXPECT_EQ(resolve_static(web, "/js/app.js"), web / "js" / "app.js");
  EXPECT_FALSE(resolve_static(web, "/../outside.txt"));
  EXPECT_FALSE(resolve_static(web, "/js/../../outside.txt"));
  EXPECT_FALSE(resolve_static(web, "/.git/config"));
  EXPECT_FALSE(resolve_static(web, "/js"));  // a folder without index.html
  EXPECT_EQ(mime_type("a.js"), "text/javascript; charset=utf-8");
  fs::remove_all(root);
}

TEST(ServeClipGlb, KeyReductionKeepsTurnsAndDropsStraightRuns) {
  // 0..10 straight up, then straight down: kept are the ends and the turn.
  std::vector<float> v;
  for (int i = 0; i <= 10; ++i) v.push_back(float(i));
  for (int i = 9; i >= 0; --i) v.push_back(float(i));
  const auto error = [&](std::size_t a, std::size_t b, std::size_t i) {
    const float x = float(i - a) / float(b - a);
    return std::abs(v[a] + x * (v[b] - v[a]) - v[i]);
  };
  EXPECT_EQ(reduce_keys(v.size(), error, 0.01f), (std::vector<std::size_t>{0, 10, 20}));
  std::vector<float> flat(8, 2.0f);
  v = flat;
  EXPECT_EQ(reduce_keys(v.size(), error, 0.01f), (std::vector<std::size_t>{0, 7}));
  EXPECT_EQ(reduce_keys(1, error, 0.01f), (std::vector<std::size_t>{0}));
}

}  // namespace
}  // namespace gestura::serve
