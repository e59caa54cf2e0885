"""The results table of ``msmesh batch`` (OUTDIR/results.jsonl and OUTDIR/results.csv) and its
HTML summary (OUTDIR/index.html, a thumbnail per mesh).

results.jsonl grows by one line per finished task while the run goes on, so that a run killed
in the middle keeps what it did; the last line of an input is its current record. At the end
the three files are rewritten (atomically) from the records of this run and of the inputs it
skipped. A record holds the options key of the task, which a rerun compares to skip inputs
already done with the same options.
"""

import csv
import html
import io
import json
import os
import tempfile
from typing import Any, Dict, Iterable, List

JSONL, CSV, HTML = "results.jsonl", "results.csv", "index.html"
COLUMNS = ["input", "output", "truth", "status", "error", "seconds", "peak_memory_mb", "faces", "estimate_mb",
           "worker", "reused", "notes", "finished", "options"]


def load(output_dir: str) -> Dict[str, Dict[str, Any]]:
    """The last record of each input in OUTDIR/results.jsonl ({} when there is none). Lines that
    do not parse (the end of a file cut by a crash) are ignored."""
    records: Dict[str, Dict[str, Any]] = {}
    try:
        with open(os.path.join(output_dir, JSONL)) as f:
            for line in f:
                try:
                    r = json.loads(line)
                except ValueError:
                    continue
                if isinstance(r, dict) and "input" in r:
                    records[r["input"]] = r
    except OSError:
        pass
    return records


def up_to_date(record: Dict[str, Any], key: str, output: str, paths: Iterable[str]) -> bool:
    """True when a previous record is a success with the same options key and output, and that
    output exists and is newer than the input (and the truth)."""
    if not record or record.get("status") != "ok" or record.get("options") != key or record.get("output") != output:
        return False
    try:
        out_time = os.stat(record["output"]).st_mtime_ns
        return all(os.stat(p).st_mtime_ns <= out_time for p in paths if p)
    except (OSError, KeyError):
        return False


class Journal:
    """Appends records to OUTDIR/results.jsonl as they arrive (one line each, flushed)."""

    def __init__(self, output_dir: str):
        self.path = os.path.join(output_dir, JSONL)
        self.file = open(self.path, "a")

    def add(self, record: Dict[str, Any]) -> None:
        self.file.write(json.dumps(record, sort_keys=True) + "\n")
        self.file.flush()

    def close(self) -> None:
        self.file.close()


def _write(path: str, text: str) -> None:
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path) or ".", prefix="." + os.path.basename(path) + ".tmp-")
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise


def _figure_names(records: List[Dict[str, Any]]) -> List[str]:
    names: List[str] = []
    for r in records:
        for k in r.get("figures") or {}:
            if k not in names:
                names.append(k)
    return names


def write_tables(output_dir: str, records: List[Dict[str, Any]]) -> None:
    """Rewrites results.jsonl and results.csv (one row per input, figures as their own columns)."""
    _write(os.path.join(output_dir, JSONL), "".join(json.dumps(r, sort_keys=True) + "\n" for r in records))
    figures = _figure_names(records)
    buffer = io.StringIO()
    writer = csv.writer(buffer)
    writer.writerow(COLUMNS + figures)
    for r in records:
        row = [r.get(c, "") for c in COLUMNS]
        row += [(r.get("figures") or {}).get(k, "") for k in figures]
        writer.writerow(["" if v is None else v for v in row])
    _write(os.path.join(output_dir, CSV), buffer.getvalue())


def write_html(output_dir: str, records: List[Dict[str, Any]], title: str) -> None:
    """OUTDIR/index.html: counts, then a row per mesh with its thumbnail, status, error, figures."""
    figures = _figure_names(records)
    ok = sum(r.get("status") == "ok" for r in records)
    failed = len(records) - ok
    total_time = sum(float(r.get("seconds") or 0) for r in records if not r.get("reused"))
    rows = []
    for r in records:
        thumb = r.get("thumbnail")
        img = ""
        if thumb and os.path.isfile(thumb):
            rel = os.path.relpath(thumb, output_dir)
            img = f'<img src="{html.escape(rel)}" width="200" height="150" loading="lazy" alt="">'
        out_rel = os.path.relpath(r["output"], output_dir) if r.get("output") else ""
        cells = [img, html.escape(r.get("input", "")),
                 f'<a href="{html.escape(out_rel)}">{html.escape(out_rel)}</a>' if r.get("status") == "ok" else "",
                 f'<span class="{html.escape(str(r.get("status")))}">{html.escape(str(r.get("status")))}'
                 f'{" (reused)" if r.get("reused") else ""}</span>',
                 html.escape(str(r.get("error") or "")), str(r.get("seconds", "")), str(r.get("peak_memory_mb", "")),
                 str(r.get("faces", ""))]
        cells += [html.escape(str((r.get("figures") or {}).get(k, ""))) for k in figures]
        rows.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    head = ["", "input", "output", "status", "error", "seconds", "peak MB", "faces"] + figures
    page = f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>
<style>body{{font-family:sans-serif;margin:1em}}table{{border-collapse:collapse}}
td,th{{border:1px solid #ccc;padding:3px 6px;font-size:13px;vertical-align:middle}}
.ok{{color:#060}}.failed{{color:#b00;font-weight:bold}}</style></head><body>
<h1>{html.escape(title)}</h1>
<p>{len(records)} meshes: {ok} done, {failed} failed; {total_time:.1f} s of work in this run.
Tables: <a href="{CSV}">{CSV}</a>, <a href="{JSONL}">{JSONL}</a>.</p>
<table><tr>{"".join(f"<th>{html.escape(h)}</th>" for h in head)}</tr>
{chr(10).join(rows)}
</table></body></html>
"""
    _write(os.path.join(output_dir, HTML), page)
