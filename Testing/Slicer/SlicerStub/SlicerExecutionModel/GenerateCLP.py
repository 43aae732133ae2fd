#!/usr/bin/python3
"""The Slicer stub's GenerateCLP: <Name>CLP.h as SEM's GenerateCLP would make it, in the ways that
matter to this project.

Usage: GenerateCLP.py --InputXML Foo.xml --OutputCxx FooCLP.h

It runs the project's own generator (CMake/GenerateCLP.py, which the standalone build uses) and
changes its output where SEM's GenerateCLP (GenerateCLP/GenerateCLP.cxx, read at SEM 6e167626e417)
differs:
- the plugin entry points: `Module_EXPORT` (visibility "default" under MODULE_HIDDEN_VISIBILITY)
  and, when `main` is a macro (SEMMacroBuildCLI compiles <Name>Lib with -Dmain=ModuleEntryPoint),
  `extern "C"` declarations of ModuleEntryPoint and GetXMLModuleDescription, which is what lets
  the launcher find the module's entry point in the shared library;
- points, regions and numeric vectors: SEM splits the text on commas (empty items dropped) and
  converts each item with atof/atoi, so `--seed a,b,c` becomes 0,0,0 and `--seed 1,2` has two
  components. The project's generator rejects both; this one does what SEM does, so that a check
  the CLI needs under Slicer has to live in the CLI's own code;
- parse errors: SEM leaves TCLAP's exception handling on, so an unknown flag or a value outside an
  enumeration makes TCLAP print `PARSE ERROR: ...` and its usage to stderr and exit(1), where the
  project's generator prints one `ERROR:` line (the one-line promise holds standalone only);
- the header is not self-contained: it includes `ModuleProcessInformation.h` (SEM's
  ModuleDescriptionParser folder, which SlicerExecutionModel_INCLUDE_DIRS holds) and defines
  `splitString`, `splitFilenames`, `GetXMLModuleDescription` and a writable, extern "C"
  `XMLModuleDescription` out of line, so two CLP headers in one binary do not link ("multiple
  definition"), as with SEM's. (SEM's own TCLAP also defines CmdLine::parse out of line; the
  stub's TCLAP is Debian's, whose definitions are inline.)
"""
import importlib.util
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT_GENERATOR = os.path.join(HERE, os.pardir, os.pardir, os.pardir, os.pardir, "CMake", "GenerateCLP.py")

SEM_EXPORT = r'''
// ---- Slicer stub: SEM's GenerateCLP includes this and exports its symbols (see GenerateCLP.py).
#include "ModuleProcessInformation.h"
#ifdef _WIN32
#define Module_EXPORT __declspec(dllexport)
#elif defined(MODULE_HIDDEN_VISIBILITY)
#define Module_EXPORT __attribute__((visibility("default")))
#else
#define Module_EXPORT
#endif
'''

SEM_SUPPORT = r'''
// ---- Slicer stub: what SEM's GenerateCLP adds or does differently (see the stub's GenerateCLP.py).
#include <cstdlib>
#include <type_traits>

#if defined(main) && !defined(REGISTER_TEST)
// If main defined as a preprocessor symbol, redefine it to the expected entry point.
#undef main
#define main ModuleEntryPoint
extern "C" {
  Module_EXPORT char* GetXMLModuleDescription();
  Module_EXPORT int ModuleEntryPoint(int, char*[]);
}
#endif

// Defined out of line, as SEM's GenerateCLP defines them: one CLP header per binary.
char* GetXMLModuleDescription() { return XMLModuleDescription; }
void splitString(const std::string& text, const std::string& separators, std::vector<std::string>& words)
{
  std::string::size_type start = text.find_first_not_of(separators);
  while (start < text.length())
  {
    std::string::size_type stop = text.find_first_of(separators, start);
    if (stop > text.length())
      stop = text.length();
    words.push_back(text.substr(start, stop - start));
    start = text.find_first_not_of(separators, stop + 1);
  }
}
void splitFilenames(const std::string& text, std::vector<std::string>& words)
{
  splitString(text, ",", words);
}

namespace sgp_sem
{
/// SEM's splitString and atof/atoi: no check of the text or of the number of components.
template<typename T>
std::vector<T> SplitWithAtof(const std::string& text, const std::string&, std::size_t)
{
  std::vector<T> values;
  const std::string separators(",");
  std::string::size_type start = text.find_first_not_of(separators);
  while (start < text.length())
  {
    std::string::size_type stop = text.find_first_of(separators, start);
    if (stop > text.length())
      stop = text.length();
    const std::string word = text.substr(start, stop - start);
    values.push_back(std::is_integral<T>::value ? static_cast<T>(std::atoi(word.c_str()))
                                                : static_cast<T>(std::atof(word.c_str())));
    start = text.find_first_not_of(separators, stop + 1);
  }
  return values;
}
} // namespace sgp_sem
'''


def main():
    args = sys.argv[1:]
    if len(args) != 4 or args[0] != "--InputXML" or args[2] != "--OutputCxx":
        sys.exit("usage: GenerateCLP.py --InputXML Foo.xml --OutputCxx FooCLP.h")
    xml, output = args[1], args[3]
    spec = importlib.util.spec_from_file_location("sgp_generate_clp", PROJECT_GENERATOR)
    generator = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(generator)
    raw, root, params = generator.parse_xml(xml)
    text = generator.generate(raw, root, params)

    text, replaced = re.subn(r"sgp::clp::SplitNumbers<", "sgp_sem::SplitWithAtof<", text)
    edits = (
        # SEM's: the description is a writable, exported array with C linkage.
        ("static const char XMLModuleDescription[] = ",
         SEM_EXPORT.lstrip("\n") + "extern \"C\" Module_EXPORT char XMLModuleDescription[] = "),
        # SEM's: TCLAP's own exception handling (PARSE ERROR, usage, exit 1).
        ("    commandLine.setExceptionHandling(false); \\\n", ""),
        ("#define GENERATE_XML", SEM_SUPPORT.lstrip("\n") + "\n#define GENERATE_XML"),
    )
    for anchor, replacement in edits:
        if text.count(anchor) != 1:
            sys.exit("GenerateCLP stub: the project's generator no longer writes %r once" % anchor)
        text = text.replace(anchor, replacement, 1)
    try:
        with open(output, encoding="utf-8") as f:
            if f.read() == text:
                return
    except OSError:
        pass
    with open(output, "w", encoding="utf-8") as f:
        f.write(text)


if __name__ == "__main__":
    main()
