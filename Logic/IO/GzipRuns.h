/// \file GzipRuns.h
/// A gzip member (RFC 1952) of a byte buffer, made for label maps: one fixed-Huffman deflate block
/// (RFC 1951 §3.2.6) in which each run of a repeated byte is its first byte as a literal and the
/// rest as copies at distance 1 (258 bytes per copy, the longest deflate has, then one shorter copy
/// or one or two literals). A label map is runs of a few labels over a mostly empty grid: the runs
/// are found eight bytes at a time, with no search for matches, several times faster than zlib's
/// fastest level on such a map (figures in docs/development.md). Any gzip reader inflates it.
///
/// Input: `data`, `size` bytes (any size; `data` may be null only when `size` is 0). Output: the
/// whole member — 10-byte header (no name, no time stamp, OS Unix), the deflate block, the CRC-32 and
/// the size modulo 2^32, little-endian. At most 9 bits a byte plus 21 bytes (no byte repeated).
/// Throws only std::bad_alloc. Its CRC-32 is libdeflate's, so it is built only where libdeflate is
/// (the standalone build, SGP_HAVE_LIBDEFLATE); Slicer's build writes every label map with ITK.
#pragma once

#include <cstddef>
#include <string>

namespace sgp
{

std::string GzipRuns(const unsigned char* data, std::size_t size);

} // namespace sgp
