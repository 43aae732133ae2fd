// Tests of the label maps' run-length gzip (GzipRuns.h): libdeflate's inflater gives back every byte
// (ITK's reader, zlib through NrrdIO, inflates the same cases in WriteLabelNrrdTest).
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <libdeflate.h>

#include "IO/GzipRuns.h"

namespace sgp
{
namespace
{

/// The bytes libdeflate inflates from `member`, which must be one whole gzip member whose CRC-32
/// and size match what it inflates to (libdeflate checks both).
std::vector<unsigned char> Inflate(const std::string& member, std::size_t size)
{
  std::vector<unsigned char> out(size + 1);
  libdeflate_decompressor* inflater = libdeflate_alloc_decompressor();
  std::size_t used = 0, written = 0;
  const libdeflate_result result =
    libdeflate_gzip_decompress_ex(inflater, member.data(), member.size(), out.data(), out.size(), &used, &written);
  libdeflate_free_decompressor(inflater);
  EXPECT_EQ(result, LIBDEFLATE_SUCCESS);
  EXPECT_EQ(used, member.size()); // nothing after the member
  out.resize(result == LIBDEFLATE_SUCCESS ? written : 0);
  return out;
}

void ExpectRoundTrip(const std::vector<unsigned char>& data, const std::string& what)
{
  const std::string member = GzipRuns(data.data(), data.size());
  EXPECT_EQ(Inflate(member, data.size()), data) << what;
}

TEST(GzipRunsTest, EmptyAndSingleByte_Inflate)
{
  ExpectRoundTrip({}, "empty");
  ExpectRoundTrip({ 0 }, "one zero");
  ExpectRoundTrip({ 255 }, "one 255");
}

TEST(GzipRunsTest, RunsOfEveryLength_Inflate)
{
  // Every run length from 1 to 800 (every length symbol and extra-bit value, 258 exactly, and
  // the remainders of one and two bytes after whole 258-byte copies), each of a byte other than its
  // neighbours', over all 256 byte values (the 8- and the 9-bit literal codes).
  std::vector<unsigned char> data;
  for (int length = 1; length <= 800; ++length)
    data.insert(data.end(), std::size_t(length), static_cast<unsigned char>((length * 37) % 256));
  ExpectRoundTrip(data, "runs 1..800");
  for (int value = 0; value < 256; ++value)
    data.insert(data.end(), std::size_t(value % 5 + 1), static_cast<unsigned char>(value));
  ExpectRoundTrip(data, "every byte value");
}

TEST(GzipRunsTest, BytesWithoutRuns_InflateWithinNineBitsEach)
{
  std::mt19937 random(7);
  std::vector<unsigned char> data(65536);
  for (unsigned char& b : data)
    b = static_cast<unsigned char>(random() & 0xFF);
  const std::string member = GzipRuns(data.data(), data.size());
  EXPECT_EQ(Inflate(member, data.size()), data);
  // At most 9 bits a literal; header, block header, end of block and trailer 21 bytes.
  EXPECT_LE(member.size(), data.size() * 9 / 8 + 21);
}

TEST(GzipRunsTest, LabelMapOfRuns_SmallAndRoundTrips)
{
  // A 200 × 150 × 60 label map: empty but for a box of label 1 with a shell of 2 and a few 3s, the
  // shape of a lumen map. Copies of 258 zeros cost 13 bits, so 1.8 MB of mostly zeros must fit
  // in a few kilobytes; coded a literal a byte it would take 2 MB.
  const long nx = 200, ny = 150, nz = 60;
  std::vector<unsigned char> data(std::size_t(nx * ny * nz), 0);
  for (long k = 10; k < 50; ++k)
    for (long j = 40; j < 110; ++j)
      for (long i = 60; i < 140; ++i)
      {
        const bool shell = i < 63 || i >= 137 || j < 43 || j >= 107;
        data[std::size_t(i + nx * (j + ny * k))] = shell ? ((i + j + k) % 17 == 0 ? 3 : 2) : 1;
      }
  const std::string member = GzipRuns(data.data(), data.size());
  EXPECT_EQ(Inflate(member, data.size()), data);
  // The most a run may cost: its first byte a literal (≤ 9 bits), 13 bits for each whole 258-byte
  // copy, then a shorter copy (≤ 8 + 5 + 5 bits) or one or two literals; plus 21 bytes of frame.
  double bits = 0.0;
  for (std::size_t n = 0; n < data.size();)
  {
    std::size_t run = 1;
    while (n + run < data.size() && data[n + run] == data[n])
      ++run;
    const std::size_t rest = (run - 1) % 258;
    bits += 9.0 + 13.0 * double((run - 1) / 258) + (rest >= 3 ? 18.0 : 9.0 * double(rest));
    n += run;
  }
  EXPECT_LE(double(member.size()), std::ceil(bits / 8.0) + 21.0);
  EXPECT_LT(member.size(), data.size() / 20); // so under 5 % of the 1.8 MB: a literal a byte would be 100 %
}

} // namespace
} // namespace sgp
