#!/usr/bin/env python3
"""Makes assets/fonts/NotoSansSC-subset.otf.br, the Chinese font pipelens embeds (brotli-compressed:
2.1 MB instead of 3.0; `vocabulary::cjk_font` unpacks it).

Source: Debian's fonts-noto-cjk (NotoSansCJK-Regular.ttc, face 2 = Simplified Chinese, OFL-1.1).
Kept: ASCII, Latin-1, Greek (for θ, α, β, λ…), the math and arrow symbols the formulas use, CJK
punctuation and full-width forms, and the 3,755 characters of GB2312 level 1 plus level 2 — every
character of the GB2312 set, so narration written by a teacher renders. Run:

    apt-get install fonts-noto-cjk && pip install fonttools brotli
    python3 assets/fonts/make-cjk-subset.py
"""
import pathlib
import subprocess

import brotli

here = pathlib.Path(__file__).resolve().parent
chars = set()
ranges = [(0x20, 0x7E), (0xA0, 0xFF), (0x370, 0x3FF), (0x2000, 0x206F), (0x2070, 0x209F),
          (0x2100, 0x214F), (0x2190, 0x21FF), (0x2200, 0x22FF), (0x2300, 0x23FF), (0x25A0, 0x25FF),
          (0x3000, 0x303F), (0xFF00, 0xFFEF)]
for lo, hi in ranges:
    chars.update(chr(c) for c in range(lo, hi + 1))
# GB2312: rows 0xA1-0xF7, cells 0xA1-0xFE (levels 1 and 2 and the symbol rows).
for hi in range(0xA1, 0xF8):
    for lo in range(0xA1, 0xFF):
        try:
            chars.add(bytes([hi, lo]).decode("gb2312"))
        except UnicodeDecodeError:
            pass
text = here / "subset-chars.txt"
text.write_text("".join(sorted(chars)), encoding="utf-8")
subprocess.run([
    "pyftsubset", "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc", "--font-number=2",
    f"--text-file={text}", f"--output-file={here / 'NotoSansSC-subset.otf'}",
    "--layout-features=*", "--no-hinting",
], check=True)
text.unlink()
otf = here / "NotoSansSC-subset.otf"
packed = here / "NotoSansSC-subset.otf.br"
packed.write_bytes(brotli.compress(otf.read_bytes(), quality=11, lgwin=24))
otf.unlink()
print("wrote", packed)
