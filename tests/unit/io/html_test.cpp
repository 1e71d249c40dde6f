// The report's HTML pieces: base64 against RFC 4648's test vectors, and escaping.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "vox/io/html.h"

namespace vox::io {
namespace {

std::vector<uint8_t> bytes(const std::string& s) { return std::vector<uint8_t>(s.begin(), s.end()); }

TEST(Html, base64IsRfc4648s) {
  EXPECT_EQ(base64(bytes("")), "");
  EXPECT_EQ(base64(bytes("f")), "Zg==");
  EXPECT_EQ(base64(bytes("fo")), "Zm8=");
  EXPECT_EQ(base64(bytes("foo")), "Zm9v");
  EXPECT_EQ(base64(bytes("foob")), "Zm9vYg==");
  EXPECT_EQ(base64(bytes("fooba")), "Zm9vYmE=");
  EXPECT_EQ(base64(bytes("foobar")), "Zm9vYmFy");
  EXPECT_EQ(pngDataUri({0x89, 'P', 'N', 'G'}), "data:image/png;base64,iVBORw==");
}

TEST(Html, textIsEscaped) {
  EXPECT_EQ(escapeHtml("a<b> & \"c\" 'd'"), "a&lt;b&gt; &amp; &quot;c&quot; &#39;d&#39;");
  EXPECT_EQ(escapeHtml("plain"), "plain");
}

}  // namespace
}  // namespace vox::io
