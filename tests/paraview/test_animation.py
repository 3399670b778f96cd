"""pvbatch test: examples/paraview/animate_noise.py steps the animation time, the noise scrolls
with it (frames differ), and the same time gives the same frame. Usage: pvbatch test_animation.py
OUTPUT_DIR"""

import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lightshafts_pvscene as scene  # noqa: E402


def main():
    import numpy as np
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    example = os.path.join(scene.ROOT, "examples", "paraview", "animate_noise.py")
    env = dict(os.environ, LIGHTSHAFTS_PARAVIEW_PLUGIN=scene.plugin_path())
    runs = {}
    for name, frames in (("a", 3), ("b", 5)):
        directory = os.path.join(out, name)
        result = subprocess.run([sys.executable if sys.executable.endswith("pvbatch") else
                                 "pvbatch", example, "--frames", str(frames), "--seconds", "8",
                                 "--size", "240", "150", "--output-dir", directory],
                                env=env, capture_output=True, text=True, timeout=300)
        print(result.stdout[-2000:], result.stderr[-2000:])
        if result.returncode != 0:
            print("FAIL: the animation script failed")
            return 1
        runs[name] = directory

    read = scene.read_png
    a = [read(os.path.join(runs["a"], f"frame_{k:04d}.png")) for k in range(3)]
    b2 = read(os.path.join(runs["b"], "frame_0002.png"))  # t = 4, as a's frame 1
    failures = []
    lit = a[0].max(axis=-1) > 20
    moved = float(np.mean(np.abs(a[0] - a[2]).max(axis=-1)[lit] >= 3))
    same = float(np.abs(a[1] - b2).max())
    print(f"lit pixels {lit.mean():.1%}; of those changed by >= 3 levels from t = 0 to 8: "
          f"{moved:.1%}; the same time in two runs: max |diff| {same}")
    if lit.mean() < 0.05:
        failures.append("no visible shafts")
    if moved < 0.05:
        failures.append("the noise does not move with the animation time")
    if same > 0:
        failures.append("the same animation time gave a different frame")
    return scene.report(failures)


if __name__ == "__main__":
    scene.finish(main())
