// libFuzzer target: the results reader (report/JsonReport.h parse_json). A file it
// accepts must also survive the documented round trip: write -> read -> write is exact.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "FuzzSupport.h"
#include "report/JsonReport.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderbed;
  auto report = parse_json(fuzz::as_text(data, size), "fuzz.json");
  if (!report) {
    (void)report.error().to_string();
    return 0;
  }
  const std::string written = to_json(*report);
  auto again = parse_json(written, "written.json");
  if (!again) {
    std::fprintf(stderr, "the reader refused what the writer wrote: %s\n", again.error().to_string().c_str());
    std::abort();
  }
  if (to_json(*again) != written) {
    std::fprintf(stderr, "write -> read -> write changed the text\n");
    std::abort();
  }
  return 0;
}
