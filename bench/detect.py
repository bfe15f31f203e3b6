"""Benchmark: precision and recall of copy detection and misconception discovery on
synthetic classes (tests/synthetic_class.py; issue 32).

Usage::

    PYTHONPATH=src python bench/detect.py                    # 3 classes of 200
    PYTHONPATH=src python bench/detect.py --classes 20 --students 200

Each class has 200 students (two exercises, six numbers), ten copying groups (a source
and one or two copiers; half copy the whole exam, half one exercise), six planted
undeclared mistakes of 5 to 9 students each, ten honest students who misread one
parameter of one exercise and carry it through every part, and honest noise (15 % of
the numbers wrong or empty). Prints, summed over the classes: the copied answers found (copiers of
the whole exam, and of one exercise), the pairs listed of two honest students (false
pairs), the pairs listed of a copier and a near twin of the source's variant, the
planted clusters of 5 or more recovered as the right perturbation, and the seconds the
findings took per class.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))


def main() -> None:
    from dynagrade.classgrade.findings import class_findings
    from synthetic_class import measure, synthetic_class

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--classes", type=int, default=3)
    parser.add_argument("--students", type=int, default=200)
    parser.add_argument("--digits", type=int, default=6,
                        help="significant digits students type the numbers they work out to")
    args = parser.parse_args()
    whole = [0, 0]
    one = [0, 0]
    false = twins = clusters = recovered = 0
    seconds = 0.0
    for seed in range(1, args.classes + 1):
        synthetic = synthetic_class(args.students, seed=seed, digits=args.digits)
        started = time.perf_counter()
        findings = class_findings(synthetic.manifest, synthetic.exercises, synthetic.records)
        seconds += time.perf_counter() - started
        m = measure(synthetic, findings)
        whole[0] += m.copied_answers_found[0]
        whole[1] += m.copied_answers[0]
        one[0] += m.copied_answers_found[1]
        one[1] += m.copied_answers[1]
        false += m.false_pairs
        twins += m.twin_pairs
        clusters += m.clusters
        recovered += m.clusters_recovered
        print(f"class {seed}: whole-exam copies {m.copied_answers_found[0]}/"
              f"{m.copied_answers[0]}, one-exercise copies {m.copied_answers_found[1]}/"
              f"{m.copied_answers[1]}, false pairs {m.false_pairs}, twin pairs "
              f"{m.twin_pairs}, clusters recovered {m.clusters_recovered}/{m.clusters}")
    print(f"{args.classes} classes of {args.students} students, numbers typed to "
          f"{args.digits} significant digits:")
    print(f"  copied answers found, copiers of the whole exam: {whole[0]}/{whole[1]} "
          f"({100 * whole[0] / max(whole[1], 1):.1f} %)")
    print(f"  copied answers found, copiers of one exercise:   {one[0]}/{one[1]} "
          f"({100 * one[0] / max(one[1], 1):.1f} %)")
    print(f"  copied answers found, all copiers:               {whole[0] + one[0]}/"
          f"{whole[1] + one[1]} ({100 * (whole[0] + one[0]) / max(whole[1] + one[1], 1):.1f} %)")
    print(f"  pairs listed of two honest students: {false}; of a copier and a near twin "
          f"of the source's variant: {twins}")
    print(f"  planted clusters of 5 or more recovered as the right perturbation: "
          f"{recovered}/{clusters} ({100 * recovered / max(clusters, 1):.1f} %)")
    print(f"  findings: {seconds / args.classes:.2f} s per class")


if __name__ == "__main__":
    main()
