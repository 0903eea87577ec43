#!/usr/bin/env python3
"""Compares the demo scene as fflight and OSMesa fed it back (examples/demo/scene.c) and
draws both.

    compare.py FFLIGHT.txt OSMESA.txt [--verbose] [--picture PNG]

Prints how many vertices were compared and the largest and mean differences of their lit
colors and window positions; --verbose also prints every vertex of both side by side.
--picture draws the lit triangles of both runs with a small rasterizer of its own (depth
test, colors interpolated across each triangle) next to a map of where the two differ, and
writes a PNG (Pillow, Debian's python3-pil). Exits 1 when a color differs by more than
COLOR_TOLERANCE or a position by more than POSITION_TOLERANCE.
"""
import argparse
import sys

# Colors: fflight evaluates in double precision, OSMesa in float; the scene's largest
# difference is far below this (the tests' own bound for a float32 result).
COLOR_TOLERANCE = 1e-5
# Window coordinates (0 to 320): float32 rounding of OSMesa's transform, about 1e-5 pixel.
POSITION_TOLERANCE = 1e-3


def read_scene(path):
    """The viewport size and the polygons of one run: lists of (x, y, z, r, g, b, a)."""
    size, polygons = None, []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "viewport":
                size = (int(words[1]), int(words[2]))
            elif words[0] == "polygon":
                polygons.append([])
            else:
                polygons[-1].append(tuple(float(v) for v in words))
    if size is None:
        sys.exit(f"{path}: no viewport line")
    return size, polygons


def largest_and_mean(differences):
    """(largest, its index, mean) of a list of numbers."""
    index = max(range(len(differences)), key=differences.__getitem__)
    return differences[index], index, sum(differences) / len(differences)


def triangles(polygons):
    """Each polygon as a fan of triangles (the scene's are triangles already)."""
    for polygon in polygons:
        for k in range(1, len(polygon) - 1):
            yield polygon[0], polygon[k], polygon[k + 1]


def rasterize(size, corners, colors):
    """An image (rows of (r, g, b) floats, top row first) of the triangles `corners` (three
    (x, y, z) window positions each) with the colors `colors` (three (r, g, b) each), depth
    tested with GL_LESS, each pixel colored at its center by interpolating its triangle's
    three colors linearly in window coordinates."""
    width, height = size
    background = (0.08, 0.08, 0.1)
    image = [[background] * width for _ in range(height)]
    depth = [[float("inf")] * width for _ in range(height)]
    for (p0, p1, p2), (c0, c1, c2) in zip(corners, colors):
        area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1])
        if area == 0:
            continue
        x_min = max(int(min(p0[0], p1[0], p2[0])), 0)
        x_max = min(int(max(p0[0], p1[0], p2[0])) + 1, width - 1)
        y_min = max(int(min(p0[1], p1[1], p2[1])), 0)
        y_max = min(int(max(p0[1], p1[1], p2[1])) + 1, height - 1)
        for y in range(y_min, y_max + 1):
            cy = y + 0.5
            row, depth_row = image[height - 1 - y], depth[height - 1 - y]
            for x in range(x_min, x_max + 1):
                cx = x + 0.5
                # Barycentric weights from the edge functions.
                w0 = ((p1[0] - cx) * (p2[1] - cy) - (p2[0] - cx) * (p1[1] - cy)) / area
                w1 = ((p2[0] - cx) * (p0[1] - cy) - (p0[0] - cx) * (p2[1] - cy)) / area
                w2 = 1.0 - w0 - w1
                if w0 < 0 or w1 < 0 or w2 < 0:
                    continue
                z = w0 * p0[2] + w1 * p1[2] + w2 * p2[2]
                if z >= depth_row[x]:
                    continue
                depth_row[x] = z
                row[x] = tuple(w0 * a + w1 * b + w2 * c for a, b, c in zip(c0, c1, c2))
    return image


def write_picture(path, size, fflight, osmesa, color_differences, scale):
    """fflight | OSMesa | where they differ, with a caption over each."""
    from PIL import Image, ImageDraw

    fflight_triangles = list(triangles(fflight))
    corners = [[v[:3] for v in t] for t in fflight_triangles]
    panels = [
        rasterize(size, corners, [[v[3:6] for v in t] for t in fflight_triangles]),
        rasterize(
            size,
            [[v[:3] for v in t] for t in triangles(osmesa)],
            [[v[3:6] for v in t] for t in triangles(osmesa)],
        ),
    ]
    # The difference of each vertex's color, as a heat color (black, red, yellow, white at
    # `scale`), interpolated across fflight's triangles.
    per_vertex = iter(color_differences)
    heat = []
    for polygon in fflight:
        values = [next(per_vertex) for _ in polygon]
        for k in range(1, len(polygon) - 1):
            heat.append([heat_color(values[i] / scale) for i in (0, k, k + 1)])
    panels.append(rasterize(size, corners, heat))

    width, height = size
    caption = 18
    picture = Image.new("RGB", (3 * width + 4, height + caption), (255, 255, 255))
    for n, panel in enumerate(panels):
        pixels = [
            tuple(min(255, max(0, round(255 * c))) for c in pixel) for row in panel for pixel in row
        ]
        image = Image.new("RGB", size)
        image.putdata(pixels)
        picture.paste(image, (n * (width + 2), caption))
    draw = ImageDraw.Draw(picture)
    captions = [
        "fflight",
        "OSMesa (Mesa llvmpipe)",
        f"|fflight - OSMesa|, white = {scale:.1e}",
    ]
    for n, text in enumerate(captions):
        draw.text((n * (width + 2) + 4, 3), text, fill=(0, 0, 0))
    picture.save(path)


def heat_color(t):
    t = min(max(t, 0.0), 1.0) * 3
    return (min(t, 1.0), min(max(t - 1, 0.0), 1.0), min(max(t - 2, 0.0), 1.0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("fflight")
    parser.add_argument("osmesa")
    parser.add_argument("--verbose", action="store_true", help="print every vertex of both")
    parser.add_argument("--picture", help="write both renderings side by side to this PNG")
    args = parser.parse_args()

    size, fflight = read_scene(args.fflight)
    osmesa_size, osmesa = read_scene(args.osmesa)
    shape = [len(p) for p in fflight]
    if size != osmesa_size or shape != [len(p) for p in osmesa]:
        sys.exit(
            f"the runs differ in shape: fflight fed back {len(fflight)} polygons, "
            f"{sum(shape)} vertices; OSMesa {len(osmesa)}, {sum(len(p) for p in osmesa)}"
        )
    pairs = [(f, o) for pf, po in zip(fflight, osmesa) for f, o in zip(pf, po)]
    colors = [max(abs(a - b) for a, b in zip(f[3:], o[3:])) for f, o in pairs]
    positions = [max(abs(a - b) for a, b in zip(f[:3], o[:3])) for f, o in pairs]

    if args.verbose:
        print(f"{'window x y z':>28}  {'fflight r g b a':>43}  {'OSMesa r g b a':>43}")
        for f, o in pairs:
            row = lambda v: " ".join(f"{c:.8f}" for c in v[3:])
            print(f"{f[0]:9.4f} {f[1]:9.4f} {f[2]:8.6f}  {row(f)}  {row(o)}")

    color_max, color_at, color_mean = largest_and_mean(colors)
    position_max, position_at, position_mean = largest_and_mean(positions)
    x, y = pairs[color_at][0][:2]
    print(
        f"fflight vs OSMesa: {len(fflight)} lit polygons, {len(pairs)} vertices compared "
        f"(GL_3D_COLOR feedback)"
    )
    print(
        f"  lit color (r g b a):     largest difference {color_max:.2e} "
        f"(vertex {color_at}, at window {x:.1f} {y:.1f}), mean {color_mean:.2e}"
    )
    print(
        f"  window position (x y z): largest difference {position_max:.2e} "
        f"(vertex {position_at}), mean {position_mean:.2e}"
    )
    ok = color_max <= COLOR_TOLERANCE and position_max <= POSITION_TOLERANCE
    print(
        f"  {'agree' if ok else 'DISAGREE'}: colors within {COLOR_TOLERANCE:g}, positions "
        f"within {POSITION_TOLERANCE:g}"
    )
    print(f"raw rows: {args.fflight}, {args.osmesa} (make demo VERBOSE=1 prints them side by side)")
    if args.picture:
        write_picture(args.picture, size, fflight, osmesa, colors, max(color_max, 1e-9))
        print(f"picture:  {args.picture} (fflight | OSMesa | where they differ)")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
