#pragma once
// The body every libFuzzer target shares: the fuzzer's bytes are the text of
// a file. Refusing it with InputError or ValidationError (a message naming the
// file and the problem) is the expected outcome for junk; anything else, i.e.
// another exception, a crash, a hang or a sanitizer report, is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "akvf/error.h"

namespace akvf::fuzz {

template <class ReadAndCheck>
int run_on_text(const std::uint8_t* data, std::size_t size, ReadAndCheck&& read_and_check) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    read_and_check(text);
  } catch (const InputError&) {
  } catch (const ValidationError&) {
  }
  return 0;
}

}  // namespace akvf::fuzz
