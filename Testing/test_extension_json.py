#!/usr/bin/python3
"""extension.json validates against Slicer's catalog-entry schema v1.0.1 (../shared/reference),
and a planted defect makes it fail, so the check can fail.

Usage: test_extension_json.py EXTENSION_JSON SCHEMA_JSON
"""
import copy
import json
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
for what, ok, detail in results:
    print("%s: %s %s" % ("PASS" if ok else "FAIL", what, detail))
failed = sum(not ok for _, ok, _ in results)
print("%d passed, %d failed" % (len(results) - failed, failed))
sys.exit(1 if failed else 0)
