// Fuzz target of the mesh readers (libFuzzer entry point): any bytes given to the PLY, OBJ and
// OFF readers must either parse or throw qd::common::Error — never crash, hang or read out of
// bounds. Built with clang -fsanitize=fuzzer when QD_LIBFUZZER is on, else with fuzz_driver.cpp.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/error.h"
#include "io/obj_reader.h"
#include "io/off_reader.h"
#include "io/ply_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    qd::io::parse_ply(bytes);
  } catch (const qd::common::Error&) {
  }
  try {
    qd::io::parse_obj(bytes);
  } catch (const qd::common::Error&) {
  }
  try {
    qd::io::parse_off(bytes);
  } catch (const qd::common::Error&) {
  }
  return 0;
}
