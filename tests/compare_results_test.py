"""scripts/compare_results.py on two hand-made result folders: a converged
case whose energy moved by rounding (kept, its iterations shown), one whose
energy moved by 1e-6 (moved), an iteration-limited case (kept whatever its
energy) and a status change (moved); --strict turns moved results into exit 1."""
import os
import subprocess
import sys
import tempfile

script = os.path.join(sys.argv[1], "scripts", "compare_results.py")
header = "mesh,method,status,reached,iterations,seconds,final_energy,lower_bound,grad_norm,max_flips,vertices,elements,message\n"
old_rows = ["A,Default,converged,1,20,1.0,4.0,4,1e-4,0,10,10,",
            "B,Default,converged,1,20,1.0,4.0,4,1e-4,0,10,10,",
            "C,SLIM,max-iterations,0,100,1.0,5.0,4,1e-1,0,10,10,",
            "D,AKVF,converged,1,30,1.0,4.5,4,1e-4,0,10,10,"]
new_rows = ["A,Default,converged,1,21,1.1,4.000000000004,4,1e-4,0,10,10,",
            "B,Default,converged,1,20,1.0,4.000004,4,1e-4,0,10,10,",
            "C,SLIM,max-iterations,0,100,1.0,5.1,4,1e-1,0,10,10,",
            "D,AKVF,max-iterations,0,1000,1.0,4.5,4,1e-2,0,10,10,"]
with tempfile.TemporaryDirectory() as tmp:
    for name, rows in (("old", old_rows), ("new", new_rows)):
        os.mkdir(os.path.join(tmp, name))
        with open(os.path.join(tmp, name, "table.csv"), "w") as f:
            f.write(header + "\n".join(rows) + "\n")
    run = lambda *extra: subprocess.run([sys.executable, script, *extra, os.path.join(tmp, "old"),
                                         os.path.join(tmp, "new")], capture_output=True, text=True)
    plain, strict = run(), run("--strict")
    lines = {line.split(" | ")[0][2:]: line for line in plain.stdout.splitlines() if line.startswith("| ") and " | " in line}
    assert plain.returncode == 0 and strict.returncode == 1, (plain, strict)
    assert "20 -> 21" in lines["A"] and lines["A"].endswith("| kept |"), lines["A"]
    assert lines["B"].endswith("| moved |"), lines["B"]
    assert lines["C"].endswith("| kept |"), lines["C"]
    assert "converged -> max-iterations" in lines["D"] and lines["D"].endswith("| moved |"), lines["D"]
    assert "2 result(s) moved" in plain.stdout, plain.stdout
    missing = subprocess.run([sys.executable, script, os.path.join(tmp, "old"), os.path.join(tmp, "none")],
                             capture_output=True, text=True)
    assert missing.returncode == 2 and "none/table.csv: no such file" in missing.stderr, missing.stderr
print("ok")
