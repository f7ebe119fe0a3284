"""python -m quasidev batch: the batch command (also `quasidev batch`, which runs this)."""

from __future__ import annotations

import argparse
import json
import sys

from ._batch import batch
from ._batch_job import STEPS
from ._batch_params import flat, parse_setting

EPILOG = """examples:
  python -m quasidev batch garments/ -o out/
  python -m quasidev batch 'scans/**/*.ply' -o out/ --steps segment,approximate --set tolerance_ae=2
  python -m quasidev batch list.txt -o out/ --steps approximate,flatten --set flatten.seam_allowance=1
  python -m quasidev batch garments/ -o out/ --scheduler tcp://head-node:8786

A rerun with the same steps and parameters skips the files already finished. Exit status: 0 when
every file is ok or skipped, 1 when a file failed (the others were run), 2 for a usage error."""


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="quasidev batch",
        description="Run segment, approximate and flatten (any subset) over many mesh files.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("inputs", nargs="+", help="folders, globs, mesh files or list files (one path per line)")
    p.add_argument("-o", "--out", required=True, help="the output folder; outputs mirror the input names")
    p.add_argument("--steps", default="approximate", help=f"comma-separated subset of {','.join(STEPS)} (default: approximate)")
    p.add_argument("--set", action="append", default=[], metavar="[STEP.]NAME=VALUE",
                   help="a parameter, by the name of the declaration (docs/reference); repeatable")
    p.add_argument("--params", metavar="FILE.json", help='parameters as JSON: {"approximate": {...}, ...} or flat')
    p.add_argument("--workers", type=int, help="local processes (default: the cores)")
    p.add_argument("--scheduler", metavar="ADDRESS", help="run on this Dask distributed scheduler instead")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    return p


def _batch_command(argv: list) -> int:
    args = _parser().parse_args(argv)
    steps = tuple(s.strip() for s in args.steps.split(",") if s.strip())
    try:
        params: dict = {}
        if args.params:
            with open(args.params, encoding="utf-8") as f:
                params = json.load(f)
        params = flat(params)
        params.update(parse_setting(text, steps) for text in args.set)
        client = None
        if args.scheduler:
            from distributed import Client

            client = Client(args.scheduler)
        summary = batch(args.inputs, args.out, steps, params, workers=args.workers, client=client,
                        progress=not args.no_progress)
    except (ValueError, OSError) as e:
        print(f"quasidev batch: error: {e}", file=sys.stderr)
        return 2
    except ImportError as e:
        print(f"quasidev batch: error: {e} (--scheduler needs Dask: pip install 'dask[distributed]')",
              file=sys.stderr)
        return 2
    if args.no_progress:  # else the bar has said them as they came
        for r in summary.records:
            if r["status"] == "failed":
                print(f"failed: {r['input']}: {r['error']}", file=sys.stderr)
    c = summary.counts
    print(f"{c['ok']} ok, {c['failed']} failed, {c['skipped']} skipped in {summary.seconds:.1f} s; "
          f"summary: {summary.summary_csv}")
    return 1 if c["failed"] else 0


def main(argv: list) -> int:
    if not argv or argv[0] != "batch":
        print("usage: python -m quasidev batch INPUTS... -o OUT [options] (--help for more)",
              file=sys.stderr)
        return 2
    return _batch_command(argv[1:])


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
