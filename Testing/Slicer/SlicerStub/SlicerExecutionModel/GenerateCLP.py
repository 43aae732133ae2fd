#!/usr/bin/python3
"""The Slicer stub's GenerateCLP: <Name>CLP.h as SEM's GenerateCLP writes it, in the ways that
matter to this project.

Usage: GenerateCLP.py --InputXML Foo.xml --OutputCxx FooCLP.h

It reads the XML with the project's own generator (CMake/GenerateCLP.py: parse_xml, Param) and
writes the header itself, following what SEM's GenerateCLP/GenerateCLP.cxx does at 91b921bd5977
(the commit Slicer 5.8.0 and 5.8.1 pin in SuperBuild/External_SlicerExecutionModel.cmake; it
differs from SEM 6e167626e417 only in an MD5 check), with the C++ types SEM's
ModuleDescriptionParser/ModuleDescriptionParser.cxx gives each tag. Written for the stub from
reading those sources; none of their code. What it does as SEM does, and the project's generator
does not:
- the header is not self-contained and has no include guard (GeneratePre): it includes the
  standard headers, TCLAP and `ModuleProcessInformation.h` (SEM's ModuleDescriptionParser folder,
  which SlicerExecutionModel_INCLUDE_DIRS holds), and nothing of the project: no `CLPSupport.h`,
  no `sgp::clp`. A file that uses those must include CLPSupport.h itself, as under SEM;
- plugin entry points (GenerateExports, GeneratePluginEntryPoints, GeneratePluginDataSymbols,
  GeneratePluginProcedures): `Module_EXPORT`, `extern "C"` declarations of ModuleEntryPoint and
  GetXMLModuleDescription when `main` is a macro (SEMMacroBuildCLI compiles <Name>Lib with
  -Dmain=ModuleEntryPoint), a writable, exported `XMLModuleDescription` with C linkage, and
  `splitString`, `splitFilenames` and `GetXMLModuleDescription` defined out of line
  (GenerateSplitString, GenerateSplitFilenames): two CLP headers in one binary do not link
  ("multiple definition");
- GENERATE_DECLARE (GenerateDeclare): scalars and enumerations are declared with their XML
  default, but a vector, point or region parameter (SEM's NeedsTemp: a C++ type std::vector<...>)
  is declared as a string `<name>Temp` holding the default text and an EMPTY `std::vector <name>`;
  the vector gets its values, the default's included, only when PARSE_ARGS parses
  (GenerateTCLAPAssignment: `<name>Temp = <name>Arg.getValue()`, then split on commas with
  splitString and each item converted with atof/atoi: `--seed a,b,c` becomes 0,0,0 and
  `--seed 1,2` has two components, so a check the CLI needs has to live in its own code).
  Booleans start false whatever the XML says; `--echo`, `--xml`, `--processinformationaddress`
  (default "0") and `--returnparameterfile` are declared and parsed like the XML's parameters;
- the command line is reordered before TCLAP sees it (GenerateTCLAPParse, the loop that
  "consolidates" argv with the deserialized parameters): every flag with its value first, in the
  order of first appearance (a repeated non-multiple flag keeps its first place and takes its last
  value), then each multiple="true" flag's values grouped by flag in sorted flag order, then the
  positional arguments. A token "-x" or "--name" that is not a flag of a non-boolean parameter
  counts as a switch and takes no value, which includes an unknown flag: `ct.nrrd --seed 0,0,0
  --noSuchFlag 3` reaches TCLAP as `--seed 0,0,0 --noSuchFlag ct.nrrd 3`, TCLAP takes
  `--noSuchFlag` for the input volume, and the error names `ct.nrrd`. "-abc" becomes the switches
  "-a", "-b", "-c". (Flag aliases are not emulated: the generator stops on one.)
- parse errors: SEM leaves TCLAP's exception handling on, so an unknown flag or a value outside an
  enumeration makes TCLAP print `PARSE ERROR: ...` and its usage to stderr and exit(1), where the
  project's generator prints one `ERROR:` line;
- the order of TCLAP's arguments (the XML's, then the four automatic ones) and its help text
  (each description followed by "(value: <default>)").
Beyond SEM, the declarations carry [[maybe_unused]] (a test need not read every parameter), and
the process-information address is read into a void* (SEM passes the typed pointer to %p).
The stub's TCLAP is Debian's, whose CmdLine is defined inline (SEM's own copy defines it out of
line); both print the same PARSE ERROR and take an unknown switch the same way.
"""
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT_GENERATOR = os.path.join(HERE, os.pardir, os.pardir, os.pardir, os.pardir, "CMake", "GenerateCLP.py")

# ModuleDescriptionParser.cxx: the C++ type of one value of each tag, and its conversion.
SCALAR_TYPES = {"integer": "int", "float": "float", "double": "double", "boolean": "bool", "string": "std::string",
                "integer-enumeration": "int", "float-enumeration": "float", "double-enumeration": "double",
                "string-enumeration": "std::string"}
VECTOR_TYPES = {"integer-vector": "int", "float-vector": "float", "double-vector": "double",
                "string-vector": "std::string"}
POINT_TAGS = {"point", "region"}
CONVERSION = {"int": "atoi", "float": "atof", "double": "atof", "std::string": "", "bool": ""}
VECTOR_CPP_TYPES = {"std::vector<int>", "std::vector<float>", "std::vector<double>", "std::vector<std::string>",
                    "std::vector<std::vector<float> >"}


class SemParameter:
    """One parameter as SEM's GenerateCLP sees it (ModuleParameter's CPPType, ArgType, StringToType)."""

    def __init__(self, tag, name, flag="", longflag="", index=None, default=None, description="", multiple=False,
                 elements=(), is_return=False):
        self.tag, self.name, self.flag, self.longflag, self.index = tag, name, flag, longflag, index
        self.default = default or ""
        self.description, self.multiple, self.elements, self.is_return = description, multiple, elements, is_return
        if tag in SCALAR_TYPES:
            self.arg_type = SCALAR_TYPES[tag]
            vector = multiple and tag in ("integer", "float", "double", "string")
            self.cpp_type = "std::vector<%s>" % self.arg_type if vector else self.arg_type
        elif tag in VECTOR_TYPES:
            self.arg_type = VECTOR_TYPES[tag]
            self.cpp_type = "std::vector<%s>" % self.arg_type
        elif tag in POINT_TAGS:
            self.arg_type = "float"
            self.cpp_type = "std::vector<std::vector<float> >" if multiple else "std::vector<float>"
        else:  # file, directory, image, geometry, transform, table, measurement, pointfile
            self.arg_type = "std::string"
            self.cpp_type = "std::vector<std::string>" if multiple else "std::string"
        self.string_to_type = CONVERSION[self.arg_type]

    @classmethod
    def from_project(cls, p):
        return cls(p.tag, p.name, p.flag, p.longflag, p.index, p.default, p.description, p.multiple, p.elements,
                   p.is_return)

    def needs_temp(self):  # GenerateCLP.cxx NeedsTemp: read as one string, split after parsing
        return self.cpp_type in VECTOR_CPP_TYPES

    def needs_quotes(self):  # NeedsQuotes: initialised from a string literal
        return ((self.cpp_type in VECTOR_CPP_TYPES or self.cpp_type == "std::string") and not self.multiple) or \
            self.cpp_type == "std::vector<std::vector<float> >"

    def has_value(self):  # HasValue
        return self.default != "" and not self.multiple

    def is_enumeration(self):
        return self.tag.endswith("-enumeration")

    def initial_value(self, cpp_string):
        """The initialiser SEM writes: the default text as is, quoted for strings and vectors."""
        if self.cpp_type == "bool":
            return "false"
        if self.needs_quotes():
            return cpp_string(self.default)
        return self.default


def automatic_parameters():
    """The four parameters GenerateDeclare adds to every module, after the XML's."""
    return [
        SemParameter("boolean", "echoSwitch", longflag="echo", default="false",
                     description="Echo the command line arguments"),
        SemParameter("boolean", "xmlSwitch", longflag="xml", default="false",
                     description="Produce xml description of command line arguments"),
        SemParameter("string", "processInformationAddressString", longflag="processinformationaddress", default="0",
                     description="Address of a structure to store process information (progress, abort, etc.)."),
        SemParameter("file", "returnParameterFile", longflag="returnparameterfile", default="",
                     description="Filename in which to write simple return parameters (int, float, int-vector, etc.) "
                                 "as opposed to bulk return parameters (image, geometry, transform, measurement, "
                                 "table)."),
    ]


PREAMBLE = r'''// Generated by the Slicer stub's GenerateCLP.py from %(xml)s, as SEM's GenerateCLP writes
// <Name>CLP.h (see that script). Not self-contained and without an include guard, as SEM's.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>
#include <map>

#include <sstream>

// (SEM's header gets strcmp, strlen and std::find through TCLAP's and the library's headers.)
#include <algorithm>
#include <cstring>

#include "tclap/CmdLine.h"
#include "ModuleProcessInformation.h"

#ifdef _WIN32
#define Module_EXPORT __declspec(dllexport)
#elif defined(MODULE_HIDDEN_VISIBILITY)
#define Module_EXPORT __attribute__((visibility("default")))
#else
#define Module_EXPORT
#endif

#if defined(main) && !defined(REGISTER_TEST)
// If main defined as a preprocessor symbol, redefine it to the expected entry point.
#undef main
#define main ModuleEntryPoint
extern "C" {
  Module_EXPORT char* GetXMLModuleDescription();
  Module_EXPORT int ModuleEntryPoint(int, char*[]);
}
#endif

extern "C" {
Module_EXPORT char XMLModuleDescription[] = %(description)s;
}

// Defined out of line, as SEM's GenerateCLP defines them: one CLP header per binary.
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

// Commas separate file names except inside double quotes, which are dropped.
void splitFilenames(const std::string& text, std::vector<std::string>& words)
{
  std::string word;
  bool quoted = false;
  bool any = false;
  for (char c : text)
  {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
    {
      if (any)
        words.push_back(word);
      word.clear();
      any = false;
      continue;
    }
    else
      word += c;
    any = true;
  }
  if (any)
    words.push_back(word);
}

char* GetXMLModuleDescription()
{
  return XMLModuleDescription;
}

namespace sgp_sem
{
/// The command line as SEM's PARSE_ARGS hands it to TCLAP (GenerateCLP.cxx, GenerateTCLAPParse):
/// argv[0]; each flag in the order of its first appearance, followed by its value when it is a flag
/// of a non-boolean parameter (a repeated one keeps its place and takes the last value; any other
/// flag, an unknown one included, takes no value); the values of each multiple flag, grouped by
/// flag in sorted order; then the positional arguments in their order. "-abc" is "-a -b -c".
inline std::vector<std::string> ReorderArguments(int argc, char* argv[], const std::vector<std::string>& valueFlags,
                                                 const std::map<std::string, bool>& multipleFlags)
{
  std::vector<std::string> flagged;
  std::map<std::string, std::vector<std::string>> multiples;
  std::vector<std::string> positionals;
  const auto has = [](const std::vector<std::string>& list, const std::string& item)
  { return std::find(list.begin(), list.end(), item) != list.end(); };
  int ac = 1;
  while (ac < argc)
  {
    const std::string arg = argv[ac++];
    const bool isFlag = (arg.size() == 2 && arg[0] == '-') || (arg.size() > 2 && arg[0] == '-' && arg[1] == '-');
    if (isFlag && !has(valueFlags, arg))
    {
      if (!has(flagged, arg))
        flagged.push_back(arg);
    }
    else if (isFlag)
    {
      const std::string value = ac < argc ? argv[ac++] : "";
      if (multipleFlags.count(arg))
        multiples[arg].push_back(value);
      else
      {
        const auto at = std::find(flagged.begin(), flagged.end(), arg);
        if (at == flagged.end() || at + 1 == flagged.end())
        {
          if (at == flagged.end())
            flagged.push_back(arg);
          flagged.push_back(value);
        }
        else
          *(at + 1) = value;
      }
    }
    else if (arg.size() > 2 && arg[0] == '-')
    {
      for (std::string::size_type i = 1; i < arg.size(); ++i)
        if (!has(flagged, std::string("-") + arg[i]))
          flagged.push_back(std::string("-") + arg[i]);
    }
    else
      positionals.push_back(arg);
  }
  std::vector<std::string> reordered{ argv[0] };
  reordered.insert(reordered.end(), flagged.begin(), flagged.end());
  for (const auto& multiple : multiples)
    for (const std::string& value : multiple.second)
    {
      reordered.push_back(multiple.first);
      reordered.push_back(value);
    }
  reordered.insert(reordered.end(), positionals.begin(), positionals.end());
  return reordered;
}
} // namespace sgp_sem

#define GENERATE_LOGO

#define GENERATE_XML \
  if (argc >= 2 && (strcmp(argv[1], "--xml") == 0)) \
  { \
    std::cout << GetXMLModuleDescription(); \
    return EXIT_SUCCESS; \
  }
'''


def macro(name, lines):
    return "#define %s \\\n" % name + "".join("  %s \\\n" % line for line in lines) + "  static_assert(true, \"\")\n"


def declare(params, cpp_string):
    """GENERATE_DECLARE: the flag tables the reordering uses, then every parameter (GenerateDeclare)."""
    lines = ["std::vector<std::string> nonbooleanFlags;", "std::map<std::string, bool> multipleFlags;"]
    for p in params:
        flags = [dash + f for dash, f in (("-", p.flag), ("--", p.longflag)) if f]
        if p.cpp_type != "bool":
            lines += ['nonbooleanFlags.emplace_back("%s");' % f for f in flags]
        if p.multiple:
            lines += ['multipleFlags["%s"] = false;' % f for f in flags]
    for p in params:
        if p.is_enumeration():
            lines.append("[[maybe_unused]] %s %s%s;" % (p.cpp_type, p.name,
                                                         " = " + p.initial_value(cpp_string) if p.has_value() else ""))
            lines.append("std::vector<%s> %sAllowed;" % (p.cpp_type, p.name))
            for element in p.elements:
                lines.append("%sAllowed.emplace_back(%s);" % (
                    p.name, cpp_string(element) if p.cpp_type == "std::string" else element))
            lines.append("TCLAP::ValuesConstraint<%s> %sAllowedVals(%sAllowed);" % (p.cpp_type, p.name, p.name))
            continue
        declared = "std::vector<std::string>" if p.multiple else "std::string" if p.needs_quotes() else p.cpp_type
        variable = p.name + ("Temp" if p.needs_temp() else "")
        if not p.has_value() and p.cpp_type != "bool":
            initial = {"int": " = 0", "float": " = 0.0f", "double": " = 0.0"}.get(p.cpp_type, "")
        else:
            initial = " = " + p.initial_value(cpp_string)
        lines.append("[[maybe_unused]] %s %s%s;" % (declared, variable, initial))
        if p.needs_temp():
            # Empty until GENERATE_TCLAP_ASSIGNMENT splits <name>Temp into it.
            lines.append("[[maybe_unused]] %s %s;" % (p.cpp_type, p.name))
    return macro("GENERATE_DECLARE", lines)


def tclap_parse(params, root, child_text, cpp_string):
    """GENERATE_TCLAP_PARSE (GenerateTCLAPParse): the TCLAP arguments, the reordering, the parse."""
    description = " ".join((child_text(root, "description") or "").split())
    full = "Description: " + description
    for label, tag in (("Author(s)", "contributor"), ("Acknowledgements", "acknowledgements")):
        text = " ".join((child_text(root, tag) or "").split())
        if text:
            full += "\n%s: %s" % (label, text)
    version = cpp_string(child_text(root, "version") or "")
    lines = ["TCLAP::CmdLine commandLine(%s, ' ', %s);" % (cpp_string(full), version), "std::ostringstream msg;"]
    missing_longflags = 0
    for p in params:
        if p.is_return:
            continue
        if p.default == "":
            lines.append("msg.str(\"\"); msg << %s;" % cpp_string(p.description))
        else:
            shown = (p.name + ("Temp" if p.needs_temp() else "")) if p.has_value() else '"None"'
            lines.append("msg.str(\"\"); msg << %s << %s << \")\";" % (cpp_string(p.description + " (value: "), shown))
        flags = "%s, %s" % (cpp_string(p.flag), cpp_string(p.longflag))
        if p.index is None and not p.longflag:
            missing_longflags += 1
            if missing_longflags > 1:
                sys.exit("GenerateCLP: Error: multiple parameters found with missing 'longflag'. "
                         "Code generation aborted.")
        if p.cpp_type == "bool":
            lines.append("TCLAP::SwitchArg %sArg(%s, msg.str(), commandLine, %s);" % (p.name, flags, p.name))
        elif p.index is not None and p.multiple:
            lines.append("TCLAP::UnlabeledMultiArg<%s> %sArg(%s, msg.str(), false, %s, commandLine);"
                         % (p.arg_type, p.name, cpp_string(p.name), cpp_string(p.cpp_type)))
        elif p.index is not None:
            lines.append("TCLAP::UnlabeledValueArg<%s> %sArg(%s, msg.str(), true, %s, %s, commandLine);"
                         % (p.cpp_type, p.name, cpp_string(p.name), p.name, cpp_string(p.cpp_type)))
        elif p.is_enumeration():
            lines.append("TCLAP::ValueArg<%s> %sArg(%s, msg.str(), false, %s, &%sAllowedVals, commandLine);"
                         % (p.cpp_type, p.name, flags, p.name, p.name))
        else:
            value_type = "std::string" if p.needs_temp() else p.cpp_type
            if p.multiple:
                lines.append("TCLAP::MultiArg<%s> %sArg(%s, msg.str(), false, %s, commandLine);"
                             % (value_type, p.name, flags, cpp_string(p.cpp_type)))
            else:
                lines.append("TCLAP::ValueArg<%s> %sArg(%s, msg.str(), false, %s, %s, commandLine);"
                             % (value_type, p.name, flags, p.name + ("Temp" if p.needs_temp() else ""),
                                cpp_string(p.cpp_type)))
    lines += [
        "try",
        "{",
        "  const std::vector<std::string> argvVector = sgp_sem::ReorderArguments(argc, argv, nonbooleanFlags, "
        "multipleFlags);",
        "  std::vector<char*> vargs;",
        "  for (const std::string& word : argvVector)",
        "    vargs.push_back(const_cast<char*>(word.c_str()));",
        "  commandLine.parse(static_cast<int>(vargs.size()), vargs.data());",
        "}",
        "catch (TCLAP::ArgException & e)",
        "{",
        "  std::cerr << \"error: \" << e.error() << \" for arg \" << e.argId() << std::endl;",
        "  return EXIT_FAILURE;",
        "}",
    ]
    return macro("GENERATE_TCLAP_PARSE", lines)


def tclap_assignment(params):
    """GENERATE_TCLAP_ASSIGNMENT (GenerateTCLAPAssignment): every value, then the vectors split."""
    lines = []
    for p in params:
        if not p.is_return:
            lines.append("%s%s = %sArg.getValue();" % (p.name, "Temp" if p.needs_temp() else "", p.name))
    for p in params:
        if p.is_return or not p.needs_temp():
            continue
        split = "splitFilenames(%s, words);" if p.tag == "file" else "splitString(%s, std::string(\",\"), words);"
        convert = "%s(word.c_str())" % p.string_to_type
        if not p.multiple:
            lines += ["{",
                      "  %s.clear();" % p.name,
                      "  std::vector<std::string> words;",
                      "  " + split % (p.name + "Temp"),
                      "  for (const std::string& word : words)",
                      "    %s.emplace_back(%s);" % (p.name, convert),
                      "}"]
        else:
            vector_of_vectors = p.cpp_type == "std::vector<std::vector<float> >"
            lines += ["for (const std::string& item : %sTemp)" % p.name,
                      "{",
                      "  std::vector<std::string> words;",
                      "  " + split % "item"]
            if vector_of_vectors:
                lines += ["  std::vector<%s> elements;" % p.arg_type,
                          "  for (const std::string& word : words)",
                          "    elements.emplace_back(%s);" % convert,
                          "  %s.emplace_back(elements);" % p.name]
            else:
                lines += ["  for (const std::string& word : words)",
                          "    %s.emplace_back(%s);" % (p.name, convert)]
            lines.append("}")
    return macro("GENERATE_TCLAP_ASSIGNMENT", lines)


def echo_arguments(params):
    """GENERATE_ECHOARGS (GenerateEchoArgs): every declared parameter, vectors item by item."""
    lines = ["if (echoSwitch)", "{", "  std::cout << \"Command Line Arguments\" << std::endl;"]
    for p in params:
        if p.needs_temp() and not p.multiple:
            lines += ["  std::cout << \"    %s: \";" % p.name,
                      "  for (const auto& item : %s)" % p.name,
                      "    std::cout << item << \", \";",
                      "  std::cout << std::endl;"]
        elif p.multiple:
            lines += ["  for (std::size_t _i = 0; _i < %sTemp.size(); _i++)" % p.name,
                      "    std::cout << \"%s[\" << _i << \"]: \" << %sTemp[_i] << std::endl;" % (p.name, p.name)]
        else:
            lines.append("  std::cout << \"    %s: \" << %s << std::endl;" % (p.name, p.name))
    lines.append("}")
    return macro("GENERATE_ECHOARGS", lines)


def generate(generator, xml_path):
    raw, root, project_params = generator.parse_xml(xml_path)
    for element in root.iter():
        if element.tag in ("flag", "longflag") and ("alias" in element.attrib or "deprecatedalias" in element.attrib):
            sys.exit("GenerateCLP stub: flag aliases (%s) are not emulated" % element.text)
    params = [SemParameter.from_project(p) for p in project_params] + automatic_parameters()
    cpp_string = generator.cpp_string
    text = PREAMBLE % {"xml": os.path.basename(xml_path), "description": cpp_string(raw)}
    text += "\n" + declare(params, cpp_string)
    text += "\n" + tclap_parse(params, root, generator.child_text, cpp_string)
    text += "\n" + tclap_assignment(params)
    text += "\n#define GENERATE_TCLAP GENERATE_TCLAP_PARSE; GENERATE_TCLAP_ASSIGNMENT\n"
    text += "\n" + echo_arguments(params)
    text += "\n" + macro("GENERATE_ProcessInformationAddressDecoding", [
        "[[maybe_unused]] ModuleProcessInformation* CLPProcessInformation = nullptr;",
        "if (!processInformationAddressString.empty())",
        "{",
        "  void* address = nullptr;",
        "  sscanf(processInformationAddressString.c_str(), \"%p\", &address);",
        "  CLPProcessInformation = static_cast<ModuleProcessInformation*>(address);",
        "}"])
    text += ("\n#define PARSE_ARGS GENERATE_LOGO; GENERATE_XML; GENERATE_DECLARE; GENERATE_TCLAP; GENERATE_ECHOARGS; "
             "GENERATE_ProcessInformationAddressDecoding; static_assert(true, \"\")\n")
    return text


def main():
    args = sys.argv[1:]
    if len(args) != 4 or args[0] != "--InputXML" or args[2] != "--OutputCxx":
        sys.exit("usage: GenerateCLP.py --InputXML Foo.xml --OutputCxx FooCLP.h")
    xml, output = args[1], args[3]
    spec = importlib.util.spec_from_file_location("sgp_generate_clp", PROJECT_GENERATOR)
    generator = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(generator)
    text = generate(generator, xml)
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
