// Fuzz target: request bodies as `gestura serve` reads them (docs/server.md): parse_request_json
// (the server's nesting and number limits), then the body read into each route's public request —
// the command layer's typed requests restricted to the fields a client may set (serve/
// public_request.hpp, app/fields.hpp `read_json`) — and checked against each field's limits. A
// bad body must be a gestura::Error (the server's 4xx), never another exception (its 500).
#include "fuzz_target.hpp"
#include "gestura/app/gloss.hpp"
#include "gestura/app/say.hpp"
#include "gestura/app/sign.hpp"
#include "gestura/serve/public_request.hpp"
#include "gestura/serve/request_json.hpp"

namespace {

template <class R>
void read_request(const nlohmann::json& body) {
  gestura::fuzz::expect_result_or_error([&] {
    R request;
    gestura::app::read_json(body, request);
    gestura::app::check_fields(request.request);
    (void)gestura::app::to_json(request.request).dump();
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gestura;
  nlohmann::json body;
  try {
    body = serve::parse_request_json(fuzz::text_of(data, size));
  } catch (const Error&) {
    return 0;  // 400
  }
  read_request<serve::Public<app::SayRequest, serve::SayFields>>(body);
  read_request<serve::Public<app::SayRequest, serve::VideoFields>>(body);
  read_request<serve::Public<app::SignRequest, serve::SignFields>>(body);
  read_request<serve::Public<app::GlossRequest, serve::GlossFields>>(body);
  return 0;
}
