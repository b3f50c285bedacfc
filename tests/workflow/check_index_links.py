# Every link and image of the main job's index page resolves offline: each href and src is a
# file beside the page or an anchor of the page; nothing is fetched from elsewhere.
# Usage: check_index_links.py out/index.html
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlparse


class Links(HTMLParser):
    def __init__(self):
        super().__init__()
        self.targets, self.ids = [], set()

    def handle_starttag(self, tag, attrs):
        for key, value in attrs:
            if key in ("href", "src") and value is not None:
                self.targets.append((tag, value))
            if key == "id":
                self.ids.add(value)


def broken_links(page):
    links = Links()
    links.feed(page.read_text())
    broken = []
    for tag, target in links.targets:
        url = urlparse(target)
        if url.scheme or url.netloc:
            broken.append(f"<{tag}> {target}: not offline")
        elif not url.path:
            if url.fragment not in links.ids:
                broken.append(f"<{tag}> {target}: no such anchor")
        elif not (page.parent / unquote(url.path)).is_file():
            broken.append(f"<{tag}> {target}: no such file")
    return broken, len(links.targets)


if __name__ == "__main__":
    broken, count = broken_links(Path(sys.argv[1]))
    for line in broken:
        print(line, file=sys.stderr)
    if broken or count == 0:
        sys.exit(f"{sys.argv[1]}: {len(broken)} of {count} links broken")
    print(f"{sys.argv[1]}: all {count} links resolve")
