# A screenshot of a page is not blank: at least 2% of its pixels differ from its most common
# grey level (the page's background), read as 8-bit grey through ffmpeg.
# Usage: check_page_not_blank.py SCREENSHOT.png
import collections
import subprocess
import sys

grey = subprocess.run(["ffmpeg", "-v", "error", "-i", sys.argv[1], "-f", "rawvideo", "-pix_fmt", "gray", "-"],
                      check=True, capture_output=True).stdout
if not grey:
    sys.exit(f"{sys.argv[1]}: no pixels")
background, count = collections.Counter(grey).most_common(1)[0]
drawn = 1.0 - count / len(grey)
if drawn < 0.02:
    sys.exit(f"{sys.argv[1]}: blank: {100 * drawn:.2f}% of the pixels differ from the background ({background})")
print(f"{sys.argv[1]}: {100 * drawn:.1f}% of the pixels drawn")
