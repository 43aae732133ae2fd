#include "IO/InflateGzipNrrd.h"

#if defined(SGP_HAVE_LIBDEFLATE)

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <system_error>
#include <thread>

#include <fcntl.h>
#include <libdeflate.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <itkByteSwapper.h>

#if defined(__linux__) && !defined(MADV_POPULATE_WRITE)
#define MADV_POPULATE_WRITE 23 // Linux 5.14; older kernels answer EINVAL and the pages fault as written
#endif

namespace sgp
{

namespace
{

/// The file mapped read-only; unmapped and closed on destruction.
class MappedFile
{
public:
  explicit MappedFile(const std::string& path)
  {
    m_Descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat status;
    if (m_Descriptor < 0 || ::fstat(m_Descriptor, &status) != 0 || !S_ISREG(status.st_mode) || status.st_size <= 0)
      return;
    void* data = ::mmap(nullptr, static_cast<std::size_t>(status.st_size), PROT_READ, MAP_PRIVATE, m_Descriptor, 0);
    if (data == MAP_FAILED)
      return;
    m_Data = static_cast<const char*>(data);
    m_Size = static_cast<std::size_t>(status.st_size);
    ::madvise(const_cast<char*>(m_Data), m_Size, MADV_SEQUENTIAL);
  }
  ~MappedFile()
  {
    if (m_Data)
      ::munmap(const_cast<char*>(m_Data), m_Size);
    if (m_Descriptor >= 0)
      ::close(m_Descriptor);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view Text() const { return { m_Data, m_Size }; }

private:
  int m_Descriptor = -1;
  const char* m_Data = nullptr;
  std::size_t m_Size = 0;
};

/// `text` without leading and trailing blanks, in lower case (NRRD's field names and the values read
/// here are matched without regard to case, as ITK's NrrdIO matches them).
std::string Normalised(std::string_view text)
{
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos)
    return {};
  const auto last = text.find_last_not_of(" \t");
  std::string out(text.substr(first, last - first + 1));
  for (char& c : out)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// The data's offset when the header (up to its blank line) declares attached, gzip-encoded data
/// of the pixel type asked for — 16-bit signed in the machine's byte order (`bytes` 2), or unsigned
/// bytes (`bytes` 1, whose byte order does not matter) — with no skips; 0 otherwise. A line is a field
/// when it has ": " (whatever else it holds, as for NrrdIO); a line without it is a comment, a
/// key:=value pair, or a header this path declines.
std::size_t GzipDataOffset(std::string_view file, int bytes)
{
  const std::size_t end = file.find("\n\n");
  if (file.substr(0, 4) != "NRRD" || end == std::string_view::npos)
    return 0;
  const std::string_view header = file.substr(0, end + 1);
  if (header.find('\r') != std::string_view::npos)
    return 0;
  bool gzip = false, typeAsked = false, nativeOrder = bytes == 1;
  for (std::size_t line = header.find('\n') + 1; line < header.size();)
  {
    const std::size_t next = header.find('\n', line);
    const std::string_view text = header.substr(line, next - line);
    line = next + 1;
    if (text.empty() || text[0] == '#')
      continue;
    const std::size_t colon = text.find(": ");
    if (colon == std::string_view::npos)
    {
      if (text.find(":=") != std::string_view::npos)
        continue; // a key:=value pair
      return 0;
    }
    const std::string field = Normalised(text.substr(0, colon)), value = Normalised(text.substr(colon + 2));
    if (field == "encoding")
      gzip = value == "gzip" || value == "gz";
    else if (field == "type")
      typeAsked = bytes == 2 ? value == "short" || value == "short int" || value == "signed short" ||
                                 value == "signed short int" || value == "int16" || value == "int16_t"
                             : value == "uchar" || value == "unsigned char" || value == "uint8" || value == "uint8_t";
    else if (field == "endian" && bytes > 1)
      nativeOrder = value == (itk::ByteSwapper<short>::SystemIsLittleEndian() ? "little" : "big");
    else if (field == "data file" || field == "datafile" ||
             ((field == "line skip" || field == "lineskip" || field == "byte skip" || field == "byteskip") &&
              value != "0"))
      return 0;
  }
  return gzip && typeAsked && nativeOrder ? end + 2 : 0;
}

} // namespace

namespace
{

/// The file's data inflated into `out` (`bytes` long) when its header declares pixels of
/// `pixelBytes` (GzipDataOffset).
bool InflateInto(const std::string& path, char* const out, const std::size_t bytes, int pixelBytes)
{
  const MappedFile file(path);
  const std::string_view text = file.Text();
  const std::size_t offset = GzipDataOffset(text, pixelBytes);
  if (offset == 0)
    return false;
  // The buffer's pages, mapped writable on the second core ahead of the inflation (their contents
  // untouched, so the race is harmless).
  std::thread mapPages;
#if defined(__linux__)
  const std::uintptr_t page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(out) + page - 1) / page * page;
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(out) + bytes) / page * page;
  if (last > first + 64 * page)
    try
    {
      mapPages = std::thread([=] { ::madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE); });
    }
    catch (const std::system_error&)
    {
      // No thread to spare: the pages fault as they are written.
    }
#endif
  libdeflate_decompressor* inflater = libdeflate_alloc_decompressor();
  std::size_t used = 0, written = 0;
  const libdeflate_result result =
    inflater
      ? libdeflate_gzip_decompress_ex(inflater, text.data() + offset, text.size() - offset, out, bytes, &used, &written)
      : LIBDEFLATE_BAD_DATA;
  libdeflate_free_decompressor(inflater);
  if (mapPages.joinable())
    mapPages.join();
  return result == LIBDEFLATE_SUCCESS && written == bytes && used == text.size() - offset;
}

} // namespace

bool InflateGzipNrrdInto(const std::string& path, CtImage& image)
{
  return InflateInto(path, reinterpret_cast<char*>(image.GetBufferPointer()),
                     image.GetPixelContainer()->Size() * sizeof(CtImage::PixelType), 2);
}

bool InflateGzipNrrdInto(const std::string& path, LabelImage& image)
{
  return InflateInto(path, reinterpret_cast<char*>(image.GetBufferPointer()), image.GetPixelContainer()->Size(), 1);
}

} // namespace sgp

#else

namespace sgp
{

bool InflateGzipNrrdInto(const std::string&, CtImage&)
{
  return false;
}

bool InflateGzipNrrdInto(const std::string&, LabelImage&)
{
  return false;
}

} // namespace sgp

#endif
