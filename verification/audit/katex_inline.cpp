#include "verification/audit/katex_inline.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace gp::verification {

namespace {

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      group = (group << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    }
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= n ? kDigits[(group >> (18 - 6 * k)) & 63] : '=';
    }
  }
  return out;
}

std::optional<KatexInline> load_katex(const std::filesystem::path& package) {
  const auto dist = package / "dist";
  if (!std::filesystem::exists(dist / "katex.min.js")) return std::nullopt;
  KatexInline k;
  k.version = nlohmann::json::parse(read(package / "package.json")).value("version", "");
  k.js = read(dist / "katex.min.js");
  // Every browser that runs the page reads woff2: the woff and ttf alternatives would only
  // double the page's size.
  const std::string css = std::regex_replace(
      read(dist / "katex.min.css"),
      std::regex(R"re(,url\(fonts/[^)]*\.(woff|ttf)\) format\("(woff|truetype)"\))re"), "");
  const std::regex font(R"re(url\(fonts/([^)]*\.woff2)\))re");
  std::size_t done = 0;
  for (auto it = std::sregex_iterator(css.begin(), css.end(), font); it != std::sregex_iterator();
       ++it) {
    k.css.append(css, done, it->position() - done);
    k.css += "url(data:font/woff2;base64," + base64(read(dist / "fonts" / (*it)[1].str())) + ")";
    done = it->position() + it->length();
  }
  k.css.append(css, done);
  return k;
}

}  // namespace gp::verification
