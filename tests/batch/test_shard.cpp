// src/batch/shard: `--shard i/n` owns the requests whose index is i modulo
// n, and anything but "i/n" with 0 <= i < n <= kMaxShards is refused with
// an InputError naming --shard.
#include "src/batch/shard.h"
#include "src/model/model.h"

#include <boost/test/unit_test.hpp>

#include <string>

using tmcert::InputError;
using tmcert::Shard;

BOOST_AUTO_TEST_SUITE(shard)

BOOST_AUTO_TEST_CASE(parses_index_and_count) {
  const Shard s = Shard::parse("2/5");
  BOOST_TEST(s.index == 2u);
  BOOST_TEST(s.count == 5u);
  const Shard whole = Shard::parse("0/1");
  BOOST_TEST(whole.index == 0u);
  BOOST_TEST(whole.count == 1u);
  const Shard last = Shard::parse("999999/1000000");
  BOOST_TEST(last.index == 999999u);
  BOOST_TEST(last.count == Shard::kMaxShards);
}

BOOST_AUTO_TEST_CASE(owns_the_requests_of_its_residue) {
  const Shard s = Shard::parse("1/3");
  for (std::size_t r = 0; r < 30; ++r) BOOST_TEST(s.owns(r) == (r % 3 == 1));
  // The shards of a count partition the requests: each one in exactly one.
  for (std::size_t r = 0; r < 30; ++r) {
    int owners = 0;
    for (std::size_t i = 0; i < 4; ++i) owners += Shard::parse(std::to_string(i) + "/4").owns(r) ? 1 : 0;
    BOOST_TEST(owners == 1);
  }
  const Shard all;  // the default: 0/1, every request
  for (std::size_t r = 0; r < 5; ++r) BOOST_TEST(all.owns(r));
}

BOOST_AUTO_TEST_CASE(refuses_anything_else_naming_the_option) {
  for (const char* bad : {"", "/", "1", "1/", "/2", "2/2", "3/2", "0/0", "-1/2", "1/-2", "+1/2", "1 /2", "1/2 ",
                          "a/2", "1/2/3", "0/1000001", "0/99999999", "1.0/2", "0x1/2"}) {
    BOOST_TEST_CONTEXT("--shard " << '"' << bad << '"') {
      try {
        Shard::parse(bad);
        BOOST_ERROR("accepted");
      } catch (const InputError& e) {
        BOOST_TEST(std::string(e.what()).find("--shard") != std::string::npos);
      }
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
