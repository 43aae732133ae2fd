#!/usr/bin/python3
"""Generate <Name>CLP.h from a Slicer Execution Model XML, the way SEM's GenerateCLP does.

Usage: GenerateCLP.py --InputXML Foo.xml --OutputCxx FooCLP.h

The generated header lets a CLI be written exactly as under Slicer's GenerateCLP:
`#include "FooCLP.h"` and `PARSE_ARGS;` at the top of main(). PARSE_ARGS
  - prints the XML and returns EXIT_SUCCESS when argv[1] is --xml (before any parsing);
  - declares one C++ variable per <name>, initialised from <default> (booleans start false, as
    in GenerateCLP: the XML default only sets the GUI);
  - parses the command line with TCLAP, adding --echo, --xml, --processinformationaddress,
    --returnparameterfile, -h/--help and --version;
  - splits comma-separated points and vectors strictly (every component must be a number, points
    must have three), enforces enumerations, and turns any parse error into one stderr line
    `ERROR: ...` and EXIT_FAILURE.
Written for StentGraftPlanner from slicer-conventions.md section 3; no SEM code is used.
"""
import argparse
import sys
import xml.etree.ElementTree as ET

SCALAR_CPP = {"integer": "int", "float": "float", "double": "double", "boolean": "bool", "string": "std::string"}
VECTOR_CPP = {"integer-vector": "int", "float-vector": "float", "double-vector": "double", "string-vector": "std::string"}
ENUM_CPP = {"integer-enumeration": "int", "float-enumeration": "float", "double-enumeration": "double",
            "string-enumeration": "std::string"}
FILE_LIKE = {"image", "geometry", "transform", "table", "measurement", "pointfile", "file", "directory"}
POINT_LIKE = {"point", "region"}


def child_text(el, tag):
    c = el.find(tag)
    return None if c is None or c.text is None else c.text.strip()


def cpp_string(s):
    out = []
    for ch in s:
        if ch == "\\":
            out.append("\\\\")
        elif ch == '"':
            out.append('\\"')
        elif ch == "\n":
            out.append("\\n")
        elif ch == "\t":
            out.append("\\t")
        elif ord(ch) < 32:
            continue
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def cpp_literal(cpp_type, value):
    if cpp_type == "std::string":
        return "std::string(%s)" % cpp_string(value)
    if cpp_type == "bool":
        return "false"
    if cpp_type == "float":
        return "%sf" % repr(float(value))
    if cpp_type == "double":
        return repr(float(value))
    return str(int(value))


class Param:
    def __init__(self, el):
        self.tag = el.tag
        self.name = child_text(el, "name") or (child_text(el, "longflag") or "").lstrip("-")
        self.flag = (child_text(el, "flag") or "").lstrip("-")
        self.longflag = (child_text(el, "longflag") or "").lstrip("-")
        self.index = child_text(el, "index")
        self.channel = child_text(el, "channel")
        self.default = child_text(el, "default")
        self.description = " ".join((child_text(el, "description") or "").split())
        self.multiple = el.attrib.get("multiple") == "true"
        self.elements = [e.text.strip() for e in el.findall("element") if e.text]
        self.is_return = self.channel == "output" and not self.flag and not self.longflag and self.index is None

    def element_type(self):
        """C++ type of one value."""
        if self.tag in SCALAR_CPP:
            return SCALAR_CPP[self.tag]
        if self.tag in ENUM_CPP:
            return ENUM_CPP[self.tag]
        if self.tag in VECTOR_CPP:
            return VECTOR_CPP[self.tag]
        if self.tag in POINT_LIKE:
            return "float"
        return "std::string"

    def cpp_type(self):
        t = self.element_type()
        if self.tag in VECTOR_CPP or self.tag in POINT_LIKE:
            t = "std::vector<%s>" % t
        if self.multiple and self.tag not in VECTOR_CPP:
            t = "std::vector<%s>" % t
        return t

    def declaration(self):
        t = self.cpp_type()
        if self.tag == "boolean":
            return "bool %s = false;" % self.name
        if self.multiple or self.default is None or self.default == "":
            return "%s %s{};" % (t, self.name)
        if self.tag in VECTOR_CPP or self.tag in POINT_LIKE:
            values = [v.strip() for v in self.default.split(",")]
            return "%s %s{%s};" % (t, self.name, ", ".join(cpp_literal(self.element_type(), v) for v in values))
        return "%s %s = %s;" % (t, self.name, cpp_literal(self.element_type(), self.default))


def parse_xml(path):
    raw = open(path, encoding="utf-8").read()
    if not raw.startswith("<?xml "):
        sys.exit("GenerateCLP.py: %s does not start with '<?xml ' at byte 0" % path)
    root = ET.fromstring(raw)
    params = []
    for group in root.findall("parameters"):
        for el in group:
            if el.tag in ("label", "description"):
                continue
            params.append(Param(el))
    return raw, root, params


def generate(raw, root, params):
    title = child_text(root, "title") or ""
    description = " ".join((child_text(root, "description") or "").split())
    contributor = child_text(root, "contributor") or ""
    acknowledgements = " ".join((child_text(root, "acknowledgements") or "").split())
    version = child_text(root, "version") or "0"
    full = "Description: " + description
    if contributor:
        full += "\nAuthor(s): " + contributor
    if acknowledgements:
        full += "\nAcknowledgements: " + acknowledgements

    L = []
    w = L.append
    w("// Generated by CMake/GenerateCLP.py from the module's XML. Do not edit.")
    w("#pragma once")
    w("#include <cstdlib>")
    w("#include <cstring>")
    w("#include <iostream>")
    w("#include <string>")
    w("#include <vector>")
    w("#include <tclap/CmdLine.h>")
    w('#include "CLPSupport.h"')
    w("")
    w("// The module description, printed by --xml.")
    w("static const char XMLModuleDescription[] = %s;" % cpp_string(raw))
    w("")
    w("#define GENERATE_XML \\")
    w("  if (argc >= 2 && std::strcmp(argv[1], \"--xml\") == 0) \\")
    w("  { \\")
    w("    std::cout << XMLModuleDescription; \\")
    w("    std::cout.flush(); \\")
    w("    return EXIT_SUCCESS; \\")
    w("  }")
    w("")
    w("#define GENERATE_DECLARE \\")
    # [[maybe_unused]]: a module need not read every parameter (returns, --echo, tests).
    for p in params:
        w("  [[maybe_unused]] %s \\" % p.declaration())
    w("  [[maybe_unused]] bool echoSwitch = false; \\")
    w("  [[maybe_unused]] std::string returnParameterFile; \\")
    w("  [[maybe_unused]] std::string processInformationAddressString = \"0\"; \\")
    w("  static_assert(true, \"\")")
    w("")
    w("#define GENERATE_TCLAP \\")
    w("  try \\")
    w("  { \\")
    w("    TCLAP::CmdLine commandLine(%s, ' ', %s); \\" % (cpp_string(full), cpp_string(version)))
    w("    commandLine.setExceptionHandling(false); \\")
    # TCLAP lists arguments in reverse order of addition; add in reverse so help reads in XML order.
    arg_lines = []
    for p in params:
        if p.is_return:
            continue
        msg = cpp_string(p.description)
        if p.index is not None:
            kind = "UnlabeledMultiArg" if p.multiple else "UnlabeledValueArg"
            if p.multiple:
                arg_lines.append("TCLAP::UnlabeledMultiArg<std::string> %sArg(%s, %s, true, \"std::string\", commandLine);"
                                 % (p.name, cpp_string(p.name), msg))
            else:
                arg_lines.append("TCLAP::UnlabeledValueArg<std::string> %sArg(%s, %s, true, \"\", \"std::string\", commandLine);"
                                 % (p.name, cpp_string(p.name), msg))
            continue
        flag = cpp_string(p.flag)
        lflag = cpp_string(p.longflag)
        if p.tag == "boolean":
            arg_lines.append("TCLAP::SwitchArg %sArg(%s, %s, %s, commandLine, false);" % (p.name, flag, lflag, msg))
        elif p.tag in ENUM_CPP:
            t = p.element_type()
            allowed = ", ".join(cpp_literal(t, e) for e in p.elements)
            arg_lines.append("std::vector<%s> %sAllowed{%s};" % (t, p.name, allowed))
            arg_lines.append("TCLAP::ValuesConstraint<%s> %sConstraint(%sAllowed);" % (t, p.name, p.name))
            arg_lines.append("TCLAP::ValueArg<%s> %sArg(%s, %s, %s, false, %s, &%sConstraint, commandLine);"
                             % (t, p.name, flag, lflag, msg, p.name, p.name))
        elif p.multiple or p.tag in VECTOR_CPP or p.tag in POINT_LIKE:
            if p.multiple:
                arg_lines.append("TCLAP::MultiArg<std::string> %sArg(%s, %s, %s, false, \"std::string\", commandLine);"
                                 % (p.name, flag, lflag, msg))
            else:
                arg_lines.append("TCLAP::ValueArg<std::string> %sArg(%s, %s, %s, false, \"\", \"std::string\", commandLine);"
                                 % (p.name, flag, lflag, msg))
        else:
            t = p.element_type()
            arg_lines.append("TCLAP::ValueArg<%s> %sArg(%s, %s, %s, false, %s, %s, commandLine);"
                             % (t, p.name, flag, lflag, msg, p.name, cpp_string(t)))
    arg_lines.append("TCLAP::SwitchArg echoSwitchArg(\"\", \"echo\", \"Echo the command line arguments\", commandLine, false);")
    arg_lines.append("TCLAP::SwitchArg xmlSwitchArg(\"\", \"xml\", \"Produce xml description of command line arguments\", commandLine, false);")
    arg_lines.append("TCLAP::ValueArg<std::string> processInformationAddressArg(\"\", \"processinformationaddress\", "
                     "\"Address of a structure to store process information (progress, abort, etc.)\", false, \"0\", "
                     "\"std::string\", commandLine);")
    arg_lines.append("TCLAP::ValueArg<std::string> returnParameterFileArg(\"\", \"returnparameterfile\", "
                     "\"Filename in which to write simple return parameters (int, float, int-vector, etc.) as opposed "
                     "to bulk return parameters (image, geometry, transform, measurement, table).\", false, \"\", "
                     "\"std::string\", commandLine);")
    for line in arg_lines:
        w("    %s \\" % line)
    w("    commandLine.parse(argc, argv); \\")
    for p in params:
        if p.is_return:
            continue
        n = p.name
        if p.index is not None or p.tag == "boolean" or (p.tag in ENUM_CPP) or (
                p.tag not in VECTOR_CPP and p.tag not in POINT_LIKE and not p.multiple):
            w("    %s = %sArg.getValue(); \\" % (n, n))
        elif p.tag in POINT_LIKE:
            count = 3 if p.tag == "point" else 6
            if p.multiple:
                w("    for (const std::string& item : %sArg.getValue()) \\" % n)
                w("      %s.push_back(sgp::clp::SplitNumbers<float>(item, \"%s\", %d)); \\" % (n, p.longflag or p.flag, count))
            else:
                w("    if (%sArg.isSet()) \\" % n)
                w("      %s = sgp::clp::SplitNumbers<float>(%sArg.getValue(), \"%s\", %d); \\" % (n, n, p.longflag or p.flag, count))
        elif p.tag in VECTOR_CPP:
            t = p.element_type()
            w("    if (%sArg.isSet()) \\" % n)
            if t == "std::string":
                w("      %s = sgp::clp::SplitStrings(%sArg.getValue()); \\" % (n, n))
            else:
                w("      %s = sgp::clp::SplitNumbers<%s>(%sArg.getValue(), \"%s\", 0); \\" % (n, t, n, p.longflag or p.flag))
        else:
            w("    %s = %sArg.getValue(); \\" % (n, n))
    w("    echoSwitch = echoSwitchArg.getValue(); \\")
    w("    returnParameterFile = returnParameterFileArg.getValue(); \\")
    w("    processInformationAddressString = processInformationAddressArg.getValue(); \\")
    w("  } \\")
    w("  catch (const TCLAP::ExitException& e) \\")
    w("  { \\")
    w("    return e.getExitStatus(); \\")
    w("  } \\")
    w("  catch (const TCLAP::ArgException& e) \\")
    w("  { \\")
    w("    std::cerr << \"ERROR: \" << sgp::clp::OneLine(e.error()) << \" (argument \" << sgp::clp::OneLine(e.argId()) \\")
    w("              << \"); see --help\" << std::endl; \\")
    w("    return EXIT_FAILURE; \\")
    w("  } \\")
    w("  catch (const sgp::clp::ParseError& e) \\")
    w("  { \\")
    w("    std::cerr << \"ERROR: \" << e.what() << std::endl; \\")
    w("    return EXIT_FAILURE; \\")
    w("  } \\")
    w("  static_assert(true, \"\")")
    w("")
    w("#define GENERATE_ECHOARGS \\")
    w("  if (echoSwitch) \\")
    w("  { \\")
    w("    std::cout << \"Command Line Arguments\" << std::endl; \\")
    for p in params:
        w("    std::cout << \"    %s: \" << sgp::clp::Echo(%s) << std::endl; \\" % (p.name, p.name))
    w("  } \\")
    w("  static_assert(true, \"\")")
    w("")
    w("// --processinformationaddress is accepted for compatibility; an executable CLI reports on stdout.")
    w("#define PARSE_ARGS \\")
    w("  GENERATE_XML; \\")
    w("  GENERATE_DECLARE; \\")
    w("  GENERATE_TCLAP; \\")
    w("  GENERATE_ECHOARGS; \\")
    w("  (void)processInformationAddressString")
    w("")
    return "\n".join(L)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--InputXML", required=True)
    ap.add_argument("--OutputCxx", required=True)
    args = ap.parse_args()
    raw, root, params = parse_xml(args.InputXML)
    text = generate(raw, root, params)
    try:
        old = open(args.OutputCxx, encoding="utf-8").read()
    except OSError:
        old = None
    if old != text:
        with open(args.OutputCxx, "w", encoding="utf-8") as f:
            f.write(text)


if __name__ == "__main__":
    main()
