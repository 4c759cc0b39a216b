// The report builder's JSON text (api/json.hpp): strings escaped, doubles round-trip, layout.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "api/json.hpp"

using cmx::api::json_number;
using cmx::api::json_quote;
using cmx::api::JsonObject;

TEST_CASE("json_quote escapes what JSON requires and keeps UTF-8 text") {
  CHECK(json_quote("plain") == "\"plain\"");
  CHECK(json_quote("a\"b\\c") == "\"a\\\"b\\\\c\"");
  CHECK(json_quote("line\nnext\ttab") == "\"line\\nnext\\ttab\"");
  CHECK(json_quote(std::string("\x01", 1)) == "\"\\u0001\"");
  CHECK(json_quote("caf\xc3\xa9") == "\"caf\xc3\xa9\"");
  // Bytes that are not UTF-8 cannot stand in JSON text: they become U+FFFD.
  CHECK(json_quote("bad\xff") == "\"bad\xef\xbf\xbd\"");
}

TEST_CASE("json_number prints doubles that read back exactly, and null for non-finite") {
  CHECK(json_number(0.1) == "0.10000000000000001");
  CHECK(std::stod(json_number(1.0 / 3.0)) == 1.0 / 3.0);
  CHECK(json_number(std::numeric_limits<double>::infinity()) == "null");
  CHECK(json_number(std::nan("")) == "null");
}

TEST_CASE("JsonObject keeps insertion order and a nested object keeps its own layout") {
  JsonObject inner;
  inner.num("n", std::uint64_t(3)).flag("ok", true);
  JsonObject outer;
  outer.str("name", "x").obj("inner", inner);
  CHECK(outer.text() == "{\n  \"name\": \"x\",\n  \"inner\": {\n  \"n\": 3,\n  \"ok\": true\n}\n}");
  CHECK(JsonObject{}.text() == "{}");
}
