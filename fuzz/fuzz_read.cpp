// libFuzzer target: the WKT and GeoJSON readers. Bad text must give gh::InvalidInput and nothing
// else: any other exception escapes and aborts, a crash or hang is a finding.
#include <cstdint>
#include <string_view>

#include "ghclip/errors.h"
#include "ghclip/validate.h"
#include "ghio/formats.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const gh::Region r = gh::io::readAuto(text);
    (void)gh::normalized(r, gh::OnBadRing::Drop);
    (void)gh::io::readWkt(gh::io::writeWkt(gh::normalized(r, gh::OnBadRing::Drop)));
  } catch (const gh::InvalidInput&) {
  }
  try {
    (void)gh::io::readPair(text);
  } catch (const gh::InvalidInput&) {
  }
  return 0;
}
