#!/usr/bin/python3
"""The surgeon's own configuration through the CLI (issue 47 item 1).

Usage: test_configuration.py --phantom PHANTOM_EXE --cli SGS_EXE --schema SCHEMA --catalog DEVICES --workdir DIR

On the demo phantom (scripts/demo.sh's anatomy):
- --outputConfiguration writes the recommendation; Resources/configuration.schema.json accepts it,
  and its components are the report's order list;
- given back unchanged (--configuration) the plan simulates the same configuration: no difference,
  the same order list, the same fit check and the file it writes is the same;
- each limb one catalogue length longer, nothing else changed: exactly one difference, that limb
  "N mm longer" with where its side lands; where the consequence says it covers the internal
  iliac ostium, the simulated fit check finds that ostium covered (and at least one side does on
  this phantom: its limbs end 5-10 mm above the ostia);
- on a 20 mm neck (the plan orders an Endurant II), the main body one length shorter with the
  contralateral limb left to the plan: the gate's clearance above the bifurcation changes by the two
  bodies' gate ends (10 mm), and the contralateral side's difference says where the limb lands;
- the main body from the other side with the positions left to the plan: the limbs swap roles
  (the report's components), and the first difference says so;
- bad configurations: one ERROR line naming the entry and what was expected, no output left; the
  schema rejects the same files the reader does where the rule is the schema's.
Prints one line per check and `N passed, M failed`; exits 1 on any failure.
"""

import argparse
import copy
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sem_rules  # noqa: E402
from test_bad_input import bad_case, check, fresh_dir, results, run, run_cli  # noqa: E402

import jsonschema  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "StentGraftPlanner"))
from StentGraftPlannerLib import EditConfiguration  # noqa: E402


def plan(cli, workdir, label, volume, seed, extra):
    outdir = fresh_dir(os.path.join(workdir, "case-" + label))
    result = run_cli(cli, outdir, volume, ["--seed", seed, "--outputReport", "{outdir}/report.json",
                                           "--outputConfiguration", "{outdir}/configuration.json", *extra])
    ok = check(result.returncode == 0, f"{label}: the plan runs (exit 0)", result.stderr.strip()[-600:])
    if not ok:
        return None
    report = json.load(open(os.path.join(outdir, "report.json")))
    values = sem_rules.read_return_parameters(os.path.join(outdir, "ret.params"))
    configuration = json.load(open(os.path.join(outdir, "configuration.json")))
    return report, values, configuration


def write(workdir, name, document):
    path = os.path.join(workdir, name)
    with open(path, "w") as handle:
        handle.write(document if isinstance(document, str) else json.dumps(document, indent=1))
    return path


def next_longer(catalog, family, code):
    """The catalogue's next longer component of the same role and diameters, or None."""
    for entry in catalog["families"]:
        if entry["name"] != family:
            continue
        for group in ("limbs", "iliacExtensions", "mainBodies"):
            items = entry.get(group, {}).get("items", [])
            mine = [i for i in items if i["code"] == code]
            if not mine:
                continue
            m = mine[0]
            longer = [i for i in items if i["diameterMm"] == m["diameterMm"] and i["code"]
                      and i["distalDiameterMm"] == m["distalDiameterMm"] and i["lengthMm"] > m["lengthMm"]]
            return min(longer, key=lambda i: i["lengthMm"]) if longer else None
    return None


def catalogue_item(catalog, code):
    return next(i for f in catalog["families"] for g in ("mainBodies", "limbs", "iliacExtensions")
                for i in f.get(g, {}).get("items", []) if i["code"] == code)


def shorter_main_body(cli, workdir, catalog, phantom):
    volume = os.path.join(workdir, "neck20.nrrd")
    params = os.path.join(workdir, "neck20.params")
    result = run([phantom, "--returnparameterfile", params, "--includeBone", "--includeKidneys", "--wallThicknessMm",
                  "1.5", "--thrombusMaxThicknessMm", "12", "--tissueHu", "-100", "--rightIliacDiameterMm", "14",
                  "--leftIliacDiameterMm", "14", "--neckDiameterMm", "20", volume], workdir)
    if not check(result.returncode == 0, "the 20 mm neck phantom is generated", result.stderr[:400]):
        return
    seed = sem_rules.read_return_parameters(params)["seedRas"]
    outcome = plan(cli, workdir, "neck20", volume, seed, [])
    if not outcome:
        return
    configuration = outcome[2]
    body = catalogue_item(catalog, configuration["components"][0]["code"])
    shorter = [i for f in catalog["families"] if f["name"] == configuration["family"] for i in f["mainBodies"]["items"]
               if i["code"] and i["diameterMm"] == body["diameterMm"] and i["distalDiameterMm"] == body["distalDiameterMm"]
               and i["lengthMm"] < body["lengthMm"]]
    shorter = max(shorter, key=lambda i: i["lengthMm"]) if shorter else None
    if not check(configuration["family"] == "Endurant II" and shorter and shorter["gateEndMm"] != body["gateEndMm"],
                 "20 mm neck: an Endurant II body with a shorter sibling whose gate ends elsewhere",
                 f"{configuration['family']} {body['code']} {shorter}"):
        return
    contralateral = "left" if configuration["mainBodySide"] == "right" else "right"
    edited = copy.deepcopy(configuration)
    edited["components"][0]["code"] = shorter["code"]
    edited["components"] = [c for c in edited["components"] if c.get("side") != contralateral]
    path = write(workdir, "neck20-shorter.json", edited)
    result = plan(cli, workdir, "neck20-shorter", volume, seed, ["--configuration", path])
    if not result:
        return
    items = result[0]["deployment"]["differences"]["items"]
    first = items[0] if items else {}
    numbers = re.findall(r"ends ([0-9.]+) mm above the aortic bifurcation \(recommended: ([0-9.]+) mm\)",
                         first.get("consequence", ""))
    moved = body["gateEndMm"] - shorter["gateEndMm"]
    # The texts carry 0.1 mm: the two clearances' difference within 0.1 of the gate ends'.
    check(first.get("what") == "main body" and first["change"].startswith(
        "%g mm shorter (%s instead of %s)" % (body["lengthMm"] - shorter["lengthMm"], shorter["code"], body["code"]))
        and numbers and abs(float(numbers[0][0]) - float(numbers[0][1]) - moved) <= 0.1 + 1e-9,
        f"main body one length shorter: the gate's clearance above the bifurcation changes by {moved:g} mm",
        str(first)[:500])
    needed = [c for c in result[0]["deployment"]["components"] if c["role"] == "contralateralLimb"]
    named = [d for d in items if d["what"] in (contralateral + " limb", contralateral + " side")]
    check(needed and named and f"the {contralateral} side " in named[0]["consequence"],
          "main body one length shorter: the contralateral limb it needs is ordered and where it lands is named",
          f"{needed[:1]} {named[:1]}")


def length_of(catalog, code):
    return next(i["lengthMm"] for f in catalog["families"] for g in ("limbs", "iliacExtensions", "mainBodies")
                for i in f.get(g, {}).get("items", []) if i["code"] == code)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phantom", required=True)
    parser.add_argument("--cli", required=True)
    parser.add_argument("--schema", required=True)
    parser.add_argument("--catalog", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    workdir = fresh_dir(os.path.abspath(args.workdir))
    cli = os.path.abspath(args.cli)
    schema = json.load(open(args.schema))
    catalog = json.load(open(args.catalog))
    validator = jsonschema.Draft202012Validator(schema)
    jsonschema.Draft202012Validator.check_schema(schema)

    volume = os.path.join(workdir, "phantom.nrrd")
    params = os.path.join(workdir, "phantom.params")
    result = run([args.phantom, "--returnparameterfile", params, "--includeBone", "--includeKidneys",
                  "--wallThicknessMm", "1.5", "--thrombusMaxThicknessMm", "12", "--tissueHu", "-100",
                  "--rightIliacDiameterMm", "14", "--leftIliacDiameterMm", "14", volume], workdir)
    if not check(result.returncode == 0, "the demo phantom is generated", result.stderr[:400]):
        return 1
    seed = sem_rules.read_return_parameters(params)["seedRas"]

    recommended = plan(cli, workdir, "recommended", volume, seed, [])
    if not recommended:
        return 1
    report, values, configuration = recommended
    errors = sorted(validator.iter_errors(configuration), key=str)
    check(not errors, "the recommendation's configuration file passes the schema", str(errors[:1])[:400])
    deployment = report["deployment"]
    codes = [c["code"] for c in configuration["components"]]
    check(codes == [c["catalogueCode"] for c in deployment["components"]],
          "the file's components are the report's order list, in order", f"{codes} vs {deployment['orderList']}")
    check(deployment["given"] is False and deployment["differences"] is None,
          "without --configuration the report says the configuration is the plan's", str(deployment["given"]))

    # Given back unchanged.
    path = write(workdir, "same.json", configuration)
    same = plan(cli, workdir, "same", volume, seed, ["--configuration", path])
    if same:
        s_report, s_values, s_configuration = same
        d = s_report["deployment"]
        check(d["given"] is True and d["differences"]["items"] == [],
              "given back unchanged: no difference from the recommendation", str(d["differences"])[:400])
        check(d["orderList"] == deployment["orderList"], "given back unchanged: the same order list", d["orderList"])
        for name in ("fitCheckPassed", "coveredOstia", "rightIliacSealLength", "leftIliacSealLength"):
            check(s_values.get(name) == values.get(name), f"given back unchanged: {name} the same",
                  f"{s_values.get(name)} vs {values.get(name)}")
        check({k: v for k, v in s_configuration.items() if k != "description"}
              == {k: v for k, v in configuration.items() if k != "description"},
              "given back unchanged: the file it writes is the file given")

    # Each limb one length longer.
    covering = 0
    for index, component in enumerate(configuration["components"]):
        if component["role"] != "limb":
            continue
        longer = next_longer(catalog, configuration["family"], component["code"])
        if not check(longer is not None, f"the {component['side']} limb {component['code']} has a longer length"):
            continue
        edited = copy.deepcopy(configuration)
        edited["components"][index]["code"] = longer["code"]
        path = write(workdir, f"longer-{component['side']}.json", edited)
        outcome = plan(cli, workdir, f"longer-{component['side']}", volume, seed, ["--configuration", path])
        if not outcome:
            continue
        l_report, l_values, _ = outcome
        items = l_report["deployment"]["differences"]["items"]
        added = longer["lengthMm"] - length_of(catalog, component["code"])
        check(len(items) == 1 and items[0]["what"] == f"{component['side']} limb"
              and items[0]["change"].startswith("%g mm longer (%s instead of %s)"
                                                % (added, longer["code"], component["code"])),
              f"{component['side']} limb one length longer: exactly that difference", str(items)[:600])
        consequence = items[0]["consequence"] if items else ""
        ostium = f"{component['side']}InternalIliac"
        if f"covers the {component['side']} internal iliac ostium by" in consequence:
            covering += 1
            check(ostium in l_values.get("coveredOstia", "") and l_values.get("fitCheckPassed") == "false",
                  f"{component['side']} limb longer: the simulated fit check finds the {component['side']} internal "
                  "iliac covered, as the difference says", f"{l_values.get('coveredOstia')}: {consequence}")
        else:
            check(ostium not in l_values.get("coveredOstia", ""),
                  f"{component['side']} limb longer: the difference says it stays clear, and the fit check agrees",
                  f"{l_values.get('coveredOstia')}: {consequence}")
    check(covering >= 1, "on the demo phantom one length longer covers an internal iliac ostium on some side",
          str(covering))

    # The panel's edit (EditConfiguration: the table's choice for the last limb, the same side) gives the
    # file the direct edit gave, and the same difference.
    last = max(i for i, c in enumerate(configuration["components"]) if c["role"] == "limb")
    longer = next_longer(catalog, configuration["family"], configuration["components"][last]["code"])
    chosen = [None] * len(configuration["components"])
    chosen[last] = {"code": longer["code"]}
    panel, edits = EditConfiguration.editedConfiguration(configuration, chosen, configuration["mainBodySide"])
    direct = json.load(open(os.path.join(workdir, "longer-%s.json" % configuration["components"][last]["side"])))
    check(panel["components"] == direct["components"] and edits == [
        "%s limb: %s" % (configuration["components"][last]["side"], longer["code"])],
        "the panel's edit of the last limb is the direct edit", str(edits))
    path = write(workdir, "panel.json", panel)
    outcome = plan(cli, workdir, "panel", volume, seed, ["--configuration", path])
    if outcome:
        direct_report = json.load(open(os.path.join(workdir, "case-longer-%s" % configuration["components"][last]["side"],
                                                     "report.json")))
        check(outcome[0]["deployment"]["differences"] == direct_report["deployment"]["differences"],
              "the panel's simulation lists the direct edit's difference", str(outcome[0]["deployment"]["differences"]))

    # The main body from the other side, the positions left to the plan.
    swapped = copy.deepcopy(configuration)
    swapped["mainBodySide"] = "left" if configuration["mainBodySide"] == "right" else "right"
    for component in swapped["components"]:
        component.pop("overlapMm", None)
    path = write(workdir, "swapped.json", swapped)
    outcome = plan(cli, workdir, "swapped", volume, seed, ["--configuration", path])
    if outcome:
        w_report = outcome[0]
        roles = {(c["role"], c["side"]) for c in w_report["deployment"]["components"]}
        ipsi = swapped["mainBodySide"]
        contra = configuration["mainBodySide"]
        check(("ipsilateralLimb", ipsi) in roles and ("contralateralLimb", contra) in roles,
              "the main body from the other side: the limbs swap roles", str(sorted(roles)))
        items = w_report["deployment"]["differences"]["items"]
        check(items and items[0]["what"] == "main body side" and "swap roles" in items[0]["consequence"],
              "the main body from the other side: the first difference says the limbs swap roles", str(items)[:400])

    # A main body one length shorter, on a phantom whose plan orders an Endurant II (a 20 mm neck: its
    # 145 mm body's gate ends at 84 mm, the 124 mm body's at 74 mm), the contralateral limb left to
    # the plan: the gate's clearance above the bifurcation grows by the gate ends' difference, and the
    # contralateral side's difference names where the limb it needs lands.
    shorter_main_body(cli, workdir, catalog, args.phantom)

    # Bad configurations: one ERROR line, nothing written; the schema agrees where the rule is its.
    limb = next(i for i, c in enumerate(configuration["components"]) if c["role"] == "limb")
    bad = [
        ("unknown-code", lambda c: c["components"][limb].update(code="XX999"), ["components[%d]" % limb, "XX999",
                                                                                "expected one of"], True),
        ("misspelt-field", lambda c: c["components"][limb].update(overlapmm=30), ["overlapmm", "unknown field"],
         False),
        ("version-2", lambda c: c.update(formatVersion=2), ["formatVersion", "expected 1"], False),
        ("cuff", lambda c: c["components"][limb].update(role="aorticCuff"), ["aortic cuffs are not simulated"],
         False),
        ("no-side", lambda c: c["components"][limb].pop("side"), ["needs its side"], False),
        ("too-deep", lambda c: c["components"][limb].update(overlapMm=500.0), ["deeper than its", "let the plan"],
         True),
        ("zero-overlap", lambda c: c["components"][limb].update(overlapMm=0.0), ["cannot reach"], False),
        ("unknown-family", lambda c: c.update(family="Endurant III"), ["Endurant III", "Endurant II"], True),
    ]
    for label, edit, needles, schema_accepts in bad:
        document = copy.deepcopy(configuration)
        edit(document)
        path = write(workdir, label + ".json", document)
        bad_case(cli, workdir, "configuration-" + label, volume, ["--seed", seed, "--configuration", path,
                                                                   "--outputReport", "{outdir}/report.json"], needles)
        accepted = not list(validator.iter_errors(document))
        check(accepted == schema_accepts, f"{label}: the schema {'accepts' if schema_accepts else 'rejects'} it "
              "(the catalogue or the anatomy decides the rest)", str(accepted))
    path = write(workdir, "not-json.json", "{ \"format\": ")
    bad_case(cli, workdir, "configuration-not-json", volume, ["--seed", seed, "--configuration", path],
             ["is not valid JSON"])
    path = write(workdir, "with-device.json", configuration)
    bad_case(cli, workdir, "configuration-and-device", volume,
             ["--seed", seed, "--configuration", path, "--device", "Endurant II"], ["both given; expected one"])

    failed = results.count(False)
    print(f"{len(results) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
