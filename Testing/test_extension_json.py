#!/usr/bin/python3
"""extension.json validates against Slicer's catalog-entry schema v1.0.1 (../shared/reference),
and a planted defect makes it fail, so the check can fail. With the top-level CMakeLists.txt as a
third argument: its icon and screenshot URLs (EXTENSION_ICONURL, EXTENSION_SCREENSHOTURLS, which
Slicer's extension page shows) name files of this repository's main branch that exist here, so
they do not point at nothing once pushed (issue 33 item 7).

Usage: test_extension_json.py EXTENSION_JSON SCHEMA_JSON [CMAKELISTS_TXT]
"""
import copy
import json
import os
import re
import sys

import jsonschema

entry = json.load(open(sys.argv[1]))
schema = json.load(open(sys.argv[2]))
validator = jsonschema.Draft7Validator(schema)
results = []
errors = list(validator.iter_errors(entry))
results.append(("extension.json is valid", not errors, "; ".join(e.message for e in errors)))
for name, plant in (("unknown field", lambda e: e.update(homepage="x")), ("no scm_url", lambda e: e.pop("scm_url")),
                    ("tier 9", lambda e: e.update(tier=9))):
    broken = copy.deepcopy(entry)
    plant(broken)
    results.append(("planted defect '%s' is rejected" % name, bool(list(validator.iter_errors(broken))), ""))
if len(sys.argv) > 3:
    cmake = open(sys.argv[3]).read()
    root = os.path.dirname(os.path.abspath(sys.argv[3]))
    # The raw-file URL of a path on the repository's main branch (scm_url's repository).
    prefix = entry["scm_url"].replace("https://github.com/", "https://raw.githubusercontent.com/") + "/main/"
    for variable in ("EXTENSION_ICONURL", "EXTENSION_SCREENSHOTURLS"):
        match = re.search(r'set\(%s "([^"]*)"\)' % variable, cmake)
        urls = match.group(1).split() if match else []
        results.append(("%s is set" % variable, bool(urls), ""))
        for url in urls:
            path = url[len(prefix):] if url.startswith(prefix) else None
            results.append(("%s %s is a file of the repository" % (variable, url),
                            path is not None and os.path.isfile(os.path.join(root, path)),
                            "expected %s<path of a file here>" % prefix))
for what, ok, detail in results:
    print("%s: %s%s" % ("PASS" if ok else "FAIL", what, "" if ok or not detail else " -- " + detail))
failed = sum(not ok for _, ok, _ in results)
print("%d passed, %d failed" % (len(results) - failed, failed))
sys.exit(1 if failed else 0)
