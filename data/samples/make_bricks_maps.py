#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Makes the bundled material maps of bricks.png (run with Debian's /usr/bin/python3 and
# python3-openimageio): /usr/bin/python3 make_bricks_maps.py bricks.png bricks_height.png bricks_normal.png
# bricks_height.png: bricks.png's luminance, blurred a little; bricks_normal.png: its
# OpenGL tangent-space normal map (n = normalize(-dH/dx, dH/dy, 1/8), encoded 0.5 + 0.5 n).
import math, sys
import OpenImageIO as oiio
src = oiio.ImageBuf(sys.argv[1])
lum = oiio.ImageBufAlgo.channel_sum(src, (0.3, 0.6, 0.1))
lum = oiio.ImageBufAlgo.convolve(lum, oiio.ImageBufAlgo.make_kernel("gaussian", 3, 3))
w, h = lum.spec().width, lum.spec().height
H = [[lum.getpixel(x, y)[0] for x in range(w)] for y in range(h)]
lum.write(sys.argv[2], "uint8")
out = oiio.ImageBuf(oiio.ImageSpec(w, h, 3, "uint8"))
for y in range(h):
    for x in range(w):
        dx = 0.5 * (H[y][min(x + 1, w - 1)] - H[y][max(x - 1, 0)])
        dy = 0.5 * (H[min(y + 1, h - 1)][x] - H[max(y - 1, 0)][x])
        v = (-dx, dy, 1.0 / 8.0)
        n = math.sqrt(sum(c * c for c in v))
        out.setpixel(x, y, tuple(0.5 + 0.5 * c / n for c in v))
out.write(sys.argv[3])
