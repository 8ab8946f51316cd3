"""geomcheck — report.json against its JSON Schema (reports/report.schema.json).

usage: test_report_schema.py SCHEMA REPORT...
Each report must validate; a copy with its overall verdict removed, and one
with a query's count turned into text, must not (so the schema can fail).
Exit 77 (skipped) when no jsonschema module is installed.
"""
import copy
import json
import sys

try:
    import jsonschema
except ImportError:
    print("SKIP: no python3 jsonschema module (apt-get install python3-jsonschema)")
    sys.exit(77)

schema = json.load(open(sys.argv[1]))
validator = jsonschema.Draft202012Validator(schema)
validator.check_schema(schema)
failed = 0
for path in sys.argv[2:]:
    report = json.load(open(path))
    errors = sorted(validator.iter_errors(report), key=str)
    for e in errors[:5]:
        print(f"FAIL {path}: {'/'.join(map(str, e.absolute_path))}: {e.message}")
    failed += bool(errors)
    broken = copy.deepcopy(report)
    del broken["verdict"]
    wrong = copy.deepcopy(report)
    if wrong["queries"]:
        wrong["queries"][0]["cases"] = str(wrong["queries"][0]["cases"])
    else:  # a point-set subject's report (verify() of a triangulator)
        wrong["point_set_queries"][0]["sets"] = str(wrong["point_set_queries"][0]["sets"])
    for what, bad in (("without its verdict", broken), ("with a count as text", wrong)):
        if validator.is_valid(bad):
            print(f"FAIL {path}: a copy {what} validates: the schema cannot fail")
            failed += 1
    if not errors:
        print(f"ok {path}: {len(report['queries'])} queries, {len(report.get('point_set_queries', []))} point-set queries")
sys.exit(1 if failed else 0)
