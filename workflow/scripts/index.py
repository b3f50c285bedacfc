# The main job's index: out/index.md and out/index.html list every step with its title, its
# command, its wall time (Snakemake's benchmark file) and what its folder holds: its Markdown
# tables inline, its figures, its videos and links to its CSV files. The page works offline:
# no script, no stylesheet or font from elsewhere, every link relative to out/.
# Run by the workflow's `index` rule (workflow/Snakefile), which passes `snakemake`.
import csv
import html
import json
from pathlib import Path


def files_of(folder, out, extension):
    """The step's files of one extension, sorted, relative to out/; not a run's per-frame files."""
    found = []
    for path in sorted(folder.rglob(f"*{extension}")):
        if "frames" in path.parts or path.name.startswith("frame_"):
            continue
        found.append(path.relative_to(out).as_posix())
    return found


def wall_seconds(out, name):
    """The step's wall time from out/benchmarks/NAME.tsv, with its video parts' (each its own
    job, out/benchmarks/video-parts/NAME_*.tsv), or None when it has none."""
    files = [out / "benchmarks" / f"{name}.tsv"] + sorted((out / "benchmarks" / "video-parts").glob(f"{name}_*.tsv"))
    seconds = None
    for tsv in (f for f in files if f.exists()):
        with tsv.open() as f:
            rows = list(csv.DictReader(f, delimiter="\t"))
        if rows:
            seconds = (seconds or 0.0) + float(rows[-1]["s"])
    return seconds


def describe(out, step):
    folder = out / step["name"]
    seconds = wall_seconds(out, step["name"])
    return {
        **step,
        "status": "done" if folder.is_dir() else "not run",
        "seconds": seconds,
        "markdown": [(out / m).read_text() for m in files_of(folder, out, ".md")],
        "images": files_of(folder, out, ".png"),
        "videos": files_of(folder, out, ".mp4"),
        "tables": files_of(folder, out, ".csv"),
        "log": f"logs/{step['name']}.log",
    }


def status_text(step):
    if step["seconds"] is None:
        return step["status"]
    return f"{step['status']} in {step['seconds']:.1f} s"


def markdown_index(steps, full):
    text = ["# Results", "",
            f"Made by the main job's workflow (`snakemake{' --config full=true' if full else ''}`); each step's "
            "folder holds its run_info.txt, its log is in logs/ and its wall time in benchmarks/.", ""]
    for s in steps:
        text += [f"## {s['title']}", "", f"`{s['command']}` — {status_text(s)}", ""]
        text += [m + "\n" for m in s["markdown"]]
        text += [f"![{i}]({i})" for i in s["images"]]
        text += [f"\nVideo: [{v}]({v})" for v in s["videos"]]
        if s["tables"]:
            text.append("\nData: " + " ".join(f"[{t}]({t})" for t in s["tables"]))
        text.append("")
    return "\n".join(text) + "\n"


STYLE = """body { font-family: sans-serif; max-width: 70em; margin: 2em auto; padding: 0 1em; color: #222; }
code, pre { background: #f3f3f3; padding: 0.1em 0.3em; }
pre { overflow-x: auto; }
img, video { max-width: 100%; display: block; margin: 0.5em 0; }
.status { color: #555; }
nav li { margin: 0.1em 0; }"""


def html_step(s):
    anchor = html.escape(s["name"])
    parts = [f'<section id="{anchor}">', f"<h2>{html.escape(s['title'])}</h2>",
             f"<p><code>{html.escape(s['command'])}</code> <span class=\"status\">{html.escape(status_text(s))}"
             f" (<a href=\"{html.escape(s['log'])}\">log</a>)</span></p>"]
    parts += [f"<pre>{html.escape(m)}</pre>" for m in s["markdown"]]
    parts += [f'<a href="{html.escape(i)}"><img src="{html.escape(i)}" alt="{html.escape(i)}"></a>'
              for i in s["images"]]
    parts += [f'<video controls preload="metadata" src="{html.escape(v)}"></video>'
              f'<p><a href="{html.escape(v)}">{html.escape(v)}</a></p>' for v in s["videos"]]
    if s["tables"]:
        links = " ".join(f'<a href="{html.escape(t)}">{html.escape(t)}</a>' for t in s["tables"])
        parts.append(f"<p>Data: {links}</p>")
    parts.append("</section>")
    return "\n".join(parts)


def html_index(steps, full):
    contents = "\n".join(f'<li><a href="#{html.escape(s["name"])}">{html.escape(s["title"])}</a> '
                         f'<span class="status">{html.escape(status_text(s))}</span></li>' for s in steps)
    return "\n".join([
        "<!DOCTYPE html>", '<html lang="en">', "<head>", '<meta charset="utf-8">', "<title>Rice testbed results</title>",
        f"<style>\n{STYLE}\n</style>", "</head>", "<body>", "<h1>Results</h1>",
        f"<p>Made by the main job's workflow (<code>snakemake{' --config full=true' if full else ''}</code>). "
        "Each step's folder holds its run_info.txt; its log and wall time are linked beside its command.</p>",
        f"<nav><ol>\n{contents}\n</ol></nav>", *[html_step(s) for s in steps], "</body>", "</html>", ""])


def write_index(out, steps_json, full, markdown_path, html_path):
    steps = [describe(out, s) for s in json.loads(steps_json)]
    Path(markdown_path).write_text(markdown_index(steps, full))
    Path(html_path).write_text(html_index(steps, full))


if __name__ == "__main__" and "snakemake" in globals():
    write_index(Path(snakemake.params.out), snakemake.params.steps, snakemake.params.full,
                snakemake.output.markdown, snakemake.output.html)
