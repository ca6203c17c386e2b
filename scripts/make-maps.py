#!/usr/bin/env python3
"""Draws the maps of the map worlds (worlds/maps/), deterministically, with the standard library.

    scripts/make-maps.py            # rewrites worlds/maps/lab.pgm, lab.yaml, lot.svg, warehouse.map

- lab.pgm + lab.yaml: a ROS map server map (binary PGM, as map_saver writes it) of a small lab
  with a parking row, 6 x 4 m at 2 cm a pixel: walls, a doorway, pillars, bay dividers, unknown
  space outside the walls and a few specks of sensor noise.
- lot.svg: a parking lot drawn as Inkscape draws (layers, groups with transforms, paths with
  curves and arcs, a polygon with a hole, a non-convex car with mirrors), 3 x 2 m on the page.
- warehouse.map: a Moving AI grid of a 30 x 15 m warehouse at 5 cm a cell: rows of shelves,
  pillars, a loading bay.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "worlds", "maps")

FREE, OCCUPIED, UNKNOWN = 254, 0, 205  # map_saver's shades


def lab():
    res = 0.02
    w, h = 300, 200  # 6 x 4 m
    img = [[UNKNOWN] * w for _ in range(h)]  # img[row][col], row 0 on top

    def fill(x0, y0, x1, y1, v):  # metres in the map frame (origin at the lower-left corner)
        for j in range(int(round(y0 / res)), int(round(y1 / res))):
            for i in range(int(round(x0 / res)), int(round(x1 / res))):
                if 0 <= i < w and 0 <= j < h:
                    img[h - 1 - j][i] = v

    fill(0.2, 0.2, 5.8, 3.8, FREE)  # the room
    for x0, y0, x1, y1 in [(0.2, 0.2, 5.8, 0.3), (0.2, 3.7, 5.8, 3.8), (0.2, 0.2, 0.3, 3.8),
                           (5.7, 0.2, 5.8, 3.8)]:
        fill(x0, y0, x1, y1, OCCUPIED)  # outer walls, 10 cm
    fill(3.0, 0.3, 3.1, 2.2, OCCUPIED)  # inner wall with a 1.5 m doorway above it
    for cx, cy in [(1.5, 2.0), (4.4, 1.2)]:  # pillars, 16 cm square
        fill(cx - 0.08, cy - 0.08, cx + 0.08, cy + 0.08, OCCUPIED)
    for k in range(6):  # bay dividers along the top wall: bays 0.30 m wide, 0.30 m deep
        x = 3.4 + 0.32 * k
        fill(x, 3.4, x + 0.02, 3.7, OCCUPIED)
    for i, j in [(40, 60), (41, 60), (120, 30), (200, 150), (250, 40)]:  # noise specks
        img[h - 1 - j][i] = OCCUPIED
    fill(1.0, 0.3, 1.6, 0.6, UNKNOWN)  # a corner the scan never saw
    with open(os.path.join(OUT, "lab.pgm"), "wb") as f:
        f.write(b"P5\n# CREATOR: scripts/make-maps.py 0.020 m/pix\n%d %d\n255\n" % (w, h))
        f.write(bytes(v for row in img for v in row))
    with open(os.path.join(OUT, "lab.yaml"), "w") as f:
        f.write("image: lab.pgm\nmode: trinary\nresolution: 0.02\norigin: [-1.0, -0.5, 0.0]\n"
                "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")


LOT_SVG = """<?xml version="1.0" encoding="UTF-8"?>
<!-- A parking lot drawn for parksim's worlds/svg_lot.yaml by scripts/make-maps.py.
     3 x 2 m: the page is 3000 x 2000 mm, one user unit a millimetre. -->
<svg xmlns="http://www.w3.org/2000/svg"
     xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     width="3000mm" height="2000mm" viewBox="0 0 3000 2000">
  <g inkscape:groupmode="layer" inkscape:label="Notes" id="notes">
    <rect id="page_frame" x="0" y="0" width="3000" height="2000" style="fill:none;stroke:#999"/>
    <text x="100" y="1950">Lot drawn for parksim</text>
  </g>
  <g inkscape:groupmode="layer" inkscape:label="Walls" id="walls">
    <rect id="wall_south" x="0" y="1950" width="3000" height="50"/>
    <rect id="wall_north" x="0" y="0" width="3000" height="50"/>
    <rect id="wall_west" x="0" y="50" width="50" height="1900"/>
    <path id="wall_east_L" d="M 2950,50 H 3000 V 1950 H 2950 V 1300 H 2700 V 1250 H 2950 Z"/>
  </g>
  <g inkscape:groupmode="layer" inkscape:label="Obstacles" id="obstacles">
    <g id="angled_bays" transform="translate(1900,500) rotate(-30)">
      <rect id="divider_1" x="0" y="-300" width="20" height="300"/>
      <rect id="divider_2" x="240" y="-300" width="20" height="300"/>
      <rect id="divider_3" x="480" y="-300" width="20" height="300"/>
    </g>
    <path id="planter_ring" style="fill-rule:evenodd"
          d="M 1000,1000 m -250,0 a 250,180 0 1 0 500,0 a 250,180 0 1 0 -500,0 Z
             M 1000,1000 m -120,0 a 120,80 0 1 1 240,0 a 120,80 0 1 1 -240,0 Z"/>
    <path id="kerb_curve" d="M 300,1500 C 500,1350 700,1650 900,1500 L 900,1540 C 700,1690 500,1390 300,1540 Z"/>
    <polygon id="parked_car" points="2200,1600 2560,1600 2560,1640 2600,1640 2600,1660 2560,1660
             2560,1780 2200,1780 2200,1660 2160,1660 2160,1640 2200,1640"/>
    <circle id="bollard_1" cx="1700" cy="1400" r="30"/>
    <circle id="bollard_2" cx="1800" cy="1400" r="30"/>
    <ellipse id="tree_bed" cx="450" cy="450" rx="150" ry="90" transform="rotate(20 450 450)"/>
    <rect id="booth" x="2350" y="150" width="250" height="180" rx="40"/>
  </g>
</svg>
"""


def warehouse():
    w, h = 600, 300  # 30 x 15 m at 5 cm
    g = [["."] * w for _ in range(h)]  # g[row][col], row 0 on top

    def block(i0, j0, i1, j1, c="@"):  # cells, j from the bottom
        for j in range(j0, j1):
            for i in range(i0, i1):
                g[h - 1 - j][i] = c

    block(0, 0, w, 4)
    block(0, h - 4, w, h)
    block(0, 0, 4, h)
    block(w - 4, 0, w, h)
    # Shelf rows: 1 m deep (20 cells), 8 m long (160 cells), aisles 1.6 m (32 cells).
    for row in range(4):
        j0 = 40 + row * 52
        for col in range(2):
            i0 = 60 + col * 200
            block(i0, j0, i0 + 160, j0 + 20)
    for i, j in [(30, 150), (560, 80), (560, 220), (300, 20)]:  # pillars, 40 cm
        block(i - 4, j - 4, i + 4, j + 4, "T")
    # Loading bay: a dock with a gap along the east wall.
    block(520, 120, 524, 170)
    block(520, 190, 524, 240)
    with open(os.path.join(OUT, "warehouse.map"), "w") as f:
        f.write("type octile\nheight %d\nwidth %d\nmap\n" % (h, w))
        for row in g:
            f.write("".join(row) + "\n")


def main():
    os.makedirs(OUT, exist_ok=True)
    lab()
    with open(os.path.join(OUT, "lot.svg"), "w") as f:
        f.write(LOT_SVG)
    warehouse()


if __name__ == "__main__":
    main()
