"""The built executables, for the Python tests (VESICA_BIN_DIR names their folder)."""
import os
import subprocess

BIN = os.environ.get("VESICA_BIN_DIR", "build/bin")


def tool(*args):
    """Runs a vesica executable; its stdout, after asserting it succeeded."""
    result = subprocess.run([os.path.join(BIN, args[0]), *map(str, args[1:])],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout
