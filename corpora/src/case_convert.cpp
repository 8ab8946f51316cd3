// geomcheck — case-file converters: shape descriptions, raw fuzz inputs,
// RapidCheck counterexamples (see casefile.hpp).
#include <cstring>

#include "geomcheck/casefile.hpp"

#include "geomcheck/detail/text_format.hpp"

namespace geomcheck {

namespace {

using detail::bits_of;
using detail::from_bits;
using detail::iequals;

// --- SHA-1 (FIPS 180-4) -----------------------------------------------------

std::uint32_t rol(std::uint32_t x, int k) { return (x << k) | (x >> (32 - k)); }

void sha1_block(std::uint32_t h[5], const std::uint8_t* p) {
  std::uint32_t w[80];
  for (int i = 0; i < 16; ++i)
    w[i] = (std::uint32_t{p[4 * i]} << 24) | (std::uint32_t{p[4 * i + 1]} << 16) |
           (std::uint32_t{p[4 * i + 2]} << 8) | std::uint32_t{p[4 * i + 3]};
  for (int i = 16; i < 80; ++i) w[i] = rol(w[i - 3] ^ w[i - 8] ^ w[i - 14] ^ w[i - 16], 1);
  std::uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4];
  for (int i = 0; i < 80; ++i) {
    std::uint32_t f, k;
    if (i < 20) {
      f = (b & c) | (~b & d);
      k = 0x5A827999u;
    } else if (i < 40) {
      f = b ^ c ^ d;
      k = 0x6ED9EBA1u;
    } else if (i < 60) {
      f = (b & c) | (b & d) | (c & d);
      k = 0x8F1BBCDCu;
    } else {
      f = b ^ c ^ d;
      k = 0xCA62C1D6u;
    }
    const std::uint32_t t = rol(a, 5) + f + e + k + w[i];
    e = d;
    d = c;
    c = rol(b, 30);
    b = a;
    a = t;
  }
  h[0] += a;
  h[1] += b;
  h[2] += c;
  h[3] += d;
  h[4] += e;
}

// --- RapidCheck text --------------------------------------------------------

bool is_ident_char(char ch) {
  return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_';
}

void skip_space(std::string_view t, std::size_t& i) {
  while (i < t.size() && (t[i] == ' ' || t[i] == '\t' || t[i] == '\n' || t[i] == '\r')) ++i;
}

bool read_number(std::string_view t, std::size_t& i, double& v) {
  const std::size_t start = i;
  std::size_t j = i;
  if (j < t.size() && (t[j] == '+' || t[j] == '-')) ++j;
  if (t.size() - j >= 4 && iequals(t.substr(j, 4), "nan(")) {
    const std::size_t close = t.find(')', j);
    if (close == std::string_view::npos) return false;
    j = close + 1;
  } else {
    while (j < t.size() && t[j] != ',' && t[j] != ')' && t[j] != '}' && t[j] != ' ' && t[j] != '\t' &&
           t[j] != '\n' && t[j] != '\r')
      ++j;
  }
  const auto parsed = parse_double(t.substr(start, j - start));
  if (!parsed) return false;
  v = *parsed;
  i = j;
  return true;
}

/// Parses "{f=..., ...}" at t[i] == '{' for layout `l`; on success sets `end`.
bool parse_description_body(std::string_view t, std::size_t i, const ShapeLayout& l, std::vector<double>& out,
                            std::size_t& end) {
  std::array<bool, 16> seen{};
  out.assign(l.size, 0.0);
  ++i;  // '{'
  for (std::size_t done = 0;;) {
    skip_space(t, i);
    const std::size_t name_start = i;
    while (i < t.size() && is_ident_char(t[i])) ++i;
    const std::string_view name = t.substr(name_start, i - name_start);
    std::size_t index = l.num_fields;
    for (std::size_t k = 0; k < l.num_fields; ++k)
      if (name == l.fields[k].name) index = k;
    if (index == l.num_fields || seen[index]) return false;
    skip_space(t, i);
    if (i >= t.size() || t[i] != '=') return false;
    ++i;
    skip_space(t, i);
    const int arity = l.fields[index].arity;
    const std::size_t off = l.offset(index);
    if (arity == 1) {
      if (!read_number(t, i, out[off])) return false;
    } else {
      if (i >= t.size() || t[i] != '(') return false;
      ++i;
      for (int k = 0; k < arity; ++k) {
        skip_space(t, i);
        if (!read_number(t, i, out[off + static_cast<std::size_t>(k)])) return false;
        skip_space(t, i);
        const char want = k + 1 < arity ? ',' : ')';
        if (i >= t.size() || t[i] != want) return false;
        ++i;
      }
    }
    seen[index] = true;
    ++done;
    skip_space(t, i);
    if (i >= t.size()) return false;
    if (t[i] == '}') {
      if (done != l.num_fields) return false;
      end = i + 1;
      return true;
    }
    if (t[i] != ',') return false;
    ++i;
  }
}

/// First well-formed description of `l` at or after `from`.
bool find_description(std::string_view t, std::size_t from, const ShapeLayout& l, std::vector<double>& out,
                      std::size_t& end) {
  for (std::size_t p = t.find(l.kind, from); p != std::string_view::npos; p = t.find(l.kind, p + 1)) {
    if (p > 0 && is_ident_char(t[p - 1])) continue;
    const std::size_t brace = p + l.kind.size();
    if (brace >= t.size() || t[brace] != '{') continue;
    if (parse_description_body(t, brace, l, out, end)) return true;
  }
  return false;
}

}  // namespace

std::string describe_shape(const ShapeLayout& l, const double* v) {
  std::string s(l.kind);
  s += '{';
  std::size_t off = 0;
  for (std::size_t f = 0; f < l.num_fields; ++f) {
    if (f) s += ", ";
    s += l.fields[f].name;
    s += '=';
    const int arity = l.fields[f].arity;
    if (arity == 1) {
      s += format_double(v[off]);
    } else {
      s += '(';
      for (int k = 0; k < arity; ++k) {
        if (k) s += ", ";
        s += format_double(v[off + static_cast<std::size_t>(k)]);
      }
      s += ')';
    }
    off += static_cast<std::size_t>(arity);
  }
  s += '}';
  return s;
}

namespace {
template <class S>
std::string describe_typed(const S& s) {
  double v[ShapeTraits<S>::size];
  ShapeTraits<S>::to(s, v);
  return describe_shape(shape_layout<S>(), v);
}
}  // namespace

std::string describe_shape(const Segment& s) { return describe_typed(s); }
std::string describe_shape(const Sphere& s) { return describe_typed(s); }
std::string describe_shape(const Capsule& s) { return describe_typed(s); }
std::string describe_shape(const Cylinder& s) { return describe_typed(s); }
std::string describe_shape(const Obb& s) { return describe_typed(s); }
std::string describe_shape(const Triangle& s) { return describe_typed(s); }
std::string describe_shape(const MovingSphere& s) { return describe_typed(s); }

std::vector<double> decode_raw_doubles(const std::uint8_t* data, std::size_t size, std::size_t count) {
  std::vector<double> out(count, 0.0);
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t u = 0;
    for (std::size_t k = 0; k < 8; ++k) {
      const std::size_t at = 8 * i + k;
      if (data == nullptr || at >= size) break;
      u |= std::uint64_t{data[at]} << (8 * k);
    }
    out[i] = from_bits(u);
  }
  return out;
}

std::vector<std::uint8_t> encode_raw_doubles(const std::vector<double>& values) {
  std::vector<std::uint8_t> out;
  out.reserve(8 * values.size());
  for (double v : values) {
    const std::uint64_t u = bits_of(v);
    for (int k = 0; k < 8; ++k) out.push_back(static_cast<std::uint8_t>(u >> (8 * k)));
  }
  return out;
}

CaseFile case_from_fuzz_input(QueryId query, const std::uint8_t* data, std::size_t size,
                              std::string_view artifact_name) {
  CaseFile c;
  c.query = query;
  const std::size_t na = query_shape(query, 0).size;
  const std::size_t nb = query_shape(query, 1).size;
  const std::vector<double> v = decode_raw_doubles(data, size, na + nb);
  c.a.assign(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(na));
  c.b.assign(v.begin() + static_cast<std::ptrdiff_t>(na), v.end());
  c.found_by = artifact_name.empty() ? "fuzz sha1=" + sha1_hex(data, size) : "fuzz " + std::string(artifact_name);
  c.note = "decoded from a " + std::to_string(size) + "-byte fuzz input as raw little-endian doubles";
  if (size < 8 * (na + nb)) c.note += " (zero-padded from " + std::to_string(size) + " bytes)";
  return c;
}

std::vector<std::uint8_t> fuzz_input_from_case(const CaseFile& c) {
  std::vector<double> v = c.a;
  v.insert(v.end(), c.b.begin(), c.b.end());
  return encode_raw_doubles(v);
}

std::optional<CaseFile> case_from_rapidcheck_text(QueryId query, std::string_view text) {
  if (!is_registered(query)) return std::nullopt;
  CaseFile c;
  c.query = query;
  std::size_t end_a = 0, end_b = 0;
  if (!find_description(text, 0, query_shape(query, 0), c.a, end_a)) return std::nullopt;
  if (!find_description(text, end_a, query_shape(query, 1), c.b, end_b)) return std::nullopt;
  c.found_by = "rapidcheck";
  const std::string_view key = "reproduce=";
  const std::size_t r = text.find(key);
  if (r != std::string_view::npos) {
    std::size_t j = r + key.size();
    while (j < text.size() && (is_ident_char(text[j]) || text[j] == '-' || text[j] == '+' || text[j] == '/'))
      ++j;
    const std::string_view token = text.substr(r + key.size(), j - r - key.size());
    if (!token.empty()) c.found_by += " reproduce=" + std::string(token);
  }
  c.note = "from a RapidCheck counterexample";
  return c;
}

std::string sha1_hex(const std::uint8_t* data, std::size_t size) {
  std::uint32_t h[5] = {0x67452301u, 0xEFCDAB89u, 0x98BADCFEu, 0x10325476u, 0xC3D2E1F0u};
  std::uint8_t block[64];
  std::size_t i = 0;
  for (; data != nullptr && i + 64 <= size; i += 64) sha1_block(h, data + i);
  const std::size_t rem = data == nullptr ? 0 : size - i;
  std::memset(block, 0, sizeof block);
  if (rem) std::memcpy(block, data + i, rem);
  block[rem] = 0x80;
  if (rem >= 56) {
    sha1_block(h, block);
    std::memset(block, 0, sizeof block);
  }
  const std::uint64_t bit_len = static_cast<std::uint64_t>(data == nullptr ? 0 : size) * 8;
  for (int k = 0; k < 8; ++k) block[63 - k] = static_cast<std::uint8_t>(bit_len >> (8 * k));
  sha1_block(h, block);
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (std::uint32_t w : h)
    for (int k = 28; k >= 0; k -= 4) out += hex[(w >> k) & 15];
  return out;
}


}  // namespace geomcheck
