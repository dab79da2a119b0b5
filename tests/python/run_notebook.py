"""Execute a notebook with nbclient (every cell; a failing cell fails the run) and write the
executed copy into OUT_DIR. Usage: run_notebook.py NOTEBOOK.ipynb OUT_DIR"""
import os
import sys
import time

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError


def main():
    path, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    nb = nbformat.read(path, as_version=4)
    client = NotebookClient(nb, timeout=500, kernel_name="python3",
                            resources={"metadata": {"path": os.path.dirname(os.path.abspath(path))}})
    start = time.time()
    try:
        client.execute()
    except CellExecutionError as e:
        print(f"{path}: a cell failed:\n{e}", file=sys.stderr)
        return 1
    finally:
        nbformat.write(nb, os.path.join(out_dir, os.path.basename(path)))
    print(f"{path}: {len(nb.cells)} cells executed in {time.time() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
