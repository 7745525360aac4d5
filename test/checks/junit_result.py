"""A junit result file, one testcase per check, as catkin's run_tests expects
it in build/test_results/<package>/ (scripts/run_tests.sh counts them)."""
import os
import xml.etree.ElementTree as ET


def write_junit(path, suite, cases):
    """cases: (name, problems) pairs; a case with problems failed, each
    problem a line of its failure message."""
    failures = sum(1 for _, problems in cases if problems)
    root = ET.Element("testsuite", name=suite, tests=str(len(cases)),
                      failures=str(failures), errors="0")
    for name, problems in cases:
        case = ET.SubElement(root, "testcase", classname=suite, name=name)
        if problems:
            failure = ET.SubElement(case, "failure", message=problems[0])
            failure.text = "\n".join(problems)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)
    return failures
