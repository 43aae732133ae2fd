/// \file GzipRuns.h
/// A gzip member (RFC 1952) of a byte buffer, made for label maps: one fixed-Huffman deflate block
/// (RFC 1951 §3.2.6) in which each run of a repeated byte is its first byte as a literal and the
/// rest as copies at distance 1 (258 bytes per copy, the longest deflate has), and a byte not
/// repeated at least three times a literal. A label map is runs of a few labels over a mostly
/// empty grid: the 512 × 512 × 400 lumen label map (105 MB) becomes 0.7 MB, coded by scanning the
/// runs eight bytes at a time in 0.02 s, where zlib's fastest level searches for matches byte by
/// byte for 0.11 s (docs/development.md). Any gzip reader inflates it (tested against zlib and
/// libdeflate on runs of every length and on bytes without runs).
///
/// Input: `data` (`size` bytes; any size, also 0). Output: the whole member — 10-byte header (no
/// name, no time stamp), the deflate block, the CRC-32 and the size modulo 2^32, little-endian.
/// Worst case (no byte repeated) 9 bits a byte plus 21 bytes. Its CRC-32 is libdeflate's, so it is
/// built only where libdeflate is (the standalone build, SGP_HAVE_LIBDEFLATE); WriteImage.cxx then
/// uses it, and Slicer's build writes every label map with ITK.
#pragma once

#include <cstddef>
#include <string>

namespace sgp
{

std::string GzipRuns(const unsigned char* data, std::size_t size);

} // namespace sgp
