"""vesica's exported walls in FEBio 4, timed (bench/bench_febio.sh). Seconds, ml, %."""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build")
os.environ.setdefault("VESICA_BIN_DIR", os.path.join(BUILD, "bin"))
os.environ.setdefault("VESICA_SHARED_DIR", os.path.join(HERE, "..", "..", "..", "shared"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "simulate"))
import FebioCrossCheckTest as cases  # noqa: E402  the test's cases, run here for their times


def worst_percent(differences):
    return round(100 * max(abs(d) for _, d in differences), 3)


def main():
    if not os.path.exists(cases.FEBIO):
        print(json.dumps({"skipped": f"FEBio 4 not found at {cases.FEBIO}"}))
        return
    folder = os.path.join(BUILD, "bench", "febio")
    b = cases.balloon(_fresh(folder, "balloon"))
    w = cases.default_wall(_fresh(folder, "default_wall"))
    print(json.dumps({
        "balloon": dict(b["figures"], febio_vs_vesica_pct=worst_percent(
            cases.on_curve(b["febio"], b["steps"]))),
        "default_wall": dict(w["figures"], febio_vs_vesica_pct=worst_percent(
            cases.on_curve(w["febio"], w["filling"][:, ::-1]))),
    }, indent=2))


def _fresh(folder, name):
    path = os.path.join(folder, name)
    cases.shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


if __name__ == "__main__":
    main()
