#include "IO/GzipRuns.h"

#include <array>
#include <cstdint>
#include <cstring>

#include <libdeflate.h>

namespace sgp
{
namespace
{

/// Deflate's fixed literal/length code (RFC 1951 §3.2.6), each code bit-reversed: deflate sends a
/// Huffman code's most significant bit first into a stream filled from each byte's lowest bit.
struct FixedCode
{
  std::array<std::uint16_t, 288> bits{};
  std::array<std::uint8_t, 288> length{};
  FixedCode()
  {
    for (unsigned symbol = 0; symbol < 288; ++symbol)
    {
      unsigned code = 0, n = 0;
      if (symbol < 144)
        code = 0x30 + symbol, n = 8;
      else if (symbol < 256)
        code = 0x190 + symbol - 144, n = 9;
      else if (symbol < 280)
        code = symbol - 256, n = 7;
      else
        code = 0xC0 + symbol - 280, n = 8;
      unsigned reversed = 0;
      for (unsigned b = 0; b < n; ++b)
        reversed |= ((code >> b) & 1u) << (n - 1 - b);
      bits[symbol] = static_cast<std::uint16_t>(reversed);
      length[symbol] = static_cast<std::uint8_t>(n);
    }
  }
};

/// A copy's length, 3 to 258, as its length symbol (257–285) and extra bits (RFC 1951 §3.2.5).
struct LengthCode
{
  unsigned symbol, extraBits, extraValue;
};

LengthCode CodeLength(unsigned length)
{
  static constexpr unsigned base[29] = { 3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                         31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258 };
  static constexpr unsigned extra[29] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                          2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0 };
  if (length == 258)
    return { 285, 0, 0 }; // 258 has its own symbol (284 with all extra bits set is not valid)
  unsigned i = 27;
  while (base[i] > length)
    --i;
  return { 257 + i, extra[i], length - base[i] };
}

/// Bits appended from each byte's lowest bit up, as deflate packs them.
class BitStream
{
public:
  explicit BitStream(std::string& out)
    : m_Out(out)
  {
  }
  void Put(std::uint64_t value, unsigned count) // count ≤ 32
  {
    m_Buffer |= value << m_Count;
    m_Count += count;
    if (m_Count >= 32)
    {
      char word[4];
      for (int b = 0; b < 4; ++b)
        word[b] = static_cast<char>((m_Buffer >> (8 * b)) & 0xFF);
      m_Out.append(word, 4);
      m_Buffer >>= 32;
      m_Count -= 32;
    }
  }
  void Flush() // the last byte's unused high bits are zero
  {
    for (; m_Count > 0; m_Count = m_Count > 8 ? m_Count - 8 : 0, m_Buffer >>= 8)
      m_Out.push_back(static_cast<char>(m_Buffer & 0xFF));
  }

private:
  std::string& m_Out;
  std::uint64_t m_Buffer = 0;
  unsigned m_Count = 0;
};

/// How many of the `size` bytes at `p` equal `value`, from the first: eight at a time.
std::size_t RunOf(const unsigned char* p, std::size_t size, unsigned char value)
{
  const std::uint64_t pattern = 0x0101010101010101ull * value;
  std::size_t n = 0;
  for (; n + 8 <= size; n += 8)
  {
    std::uint64_t word;
    std::memcpy(&word, p + n, 8);
    if (word != pattern)
      break;
  }
  while (n < size && p[n] == value)
    ++n;
  return n;
}

void PutLittleEndian32(std::string& out, std::uint32_t value)
{
  for (int b = 0; b < 4; ++b)
    out.push_back(static_cast<char>((value >> (8 * b)) & 0xFF));
}

} // namespace

std::string GzipRuns(const unsigned char* data, std::size_t size)
{
  static const FixedCode code;
  std::string out = { '\x1f', '\x8b', '\x08', '\x00', '\x00', '\x00', '\x00', '\x00', '\x00', '\x03' }; // gzip, Unix
  out.reserve(64 + size / 64);
  BitStream bits(out);
  bits.Put(1, 1); // the final block
  bits.Put(1, 2); // fixed Huffman codes
  const auto literal = [&](unsigned char b) { bits.Put(code.bits[b], code.length[b]); };
  const auto copy = [&](unsigned length)
  {
    const LengthCode c = CodeLength(length);
    bits.Put(code.bits[c.symbol], code.length[c.symbol]);
    if (c.extraBits > 0)
      bits.Put(c.extraValue, c.extraBits);
    bits.Put(0, 5); // distance 1: distance code 0, five bits, no extra bits
  };
  for (std::size_t n = 0; n < size;)
  {
    const unsigned char b = data[n++];
    literal(b);
    std::size_t run = RunOf(data + n, size - n, b);
    n += run;
    for (; run >= 258; run -= 258)
      copy(258);
    if (run >= 3)
      copy(static_cast<unsigned>(run));
    else
      for (; run > 0; --run)
        literal(b);
  }
  bits.Put(code.bits[256], code.length[256]); // end of block
  bits.Flush();
  PutLittleEndian32(out, libdeflate_crc32(0, data, size));
  PutLittleEndian32(out, static_cast<std::uint32_t>(size & 0xFFFFFFFFu));
  return out;
}

} // namespace sgp
