#!/usr/bin/env python3
"""Writes data/worlds/museum.world: a small museum of 22 m x 16 m on one floor, for measuring the
semantic stack on a world nobody tuned on.

South of the building (y < 6), west to east: the entrance hall with the main entrance (two door
leaves) in the south wall, the ticket desk with the clerk's office chair, a cloakroom corner on the
west wall (coat racks, a bank of lockers, an umbrella stand), a brochure rack, a donation box, a
floor-plan information panel and one featured display case; the gift shop (shop shelves, the shop
counter with the cash register, two postcard stands); the cafe (cafe tables and chairs, the cafe
counter with the coffee machine, a waste bin) with the toilets partitioned off in its south-east
corner (two toilets, two sinks with mirrors over them, a hand dryer).
North of it (y > 6), west to east: the painting gallery (paintings on all four walls, a bench, a
rope barrier with stanchions in front of the large painting, information panels), the sculpture
hall (sculptures and busts on plinths, the large sculpture roped off, a bench) and the artefact
gallery (glass display cases, a tall wall case, a bench, the fire exit in the east wall with the
exit sign over it). Security cameras high in the corners, fire extinguishers on the walls, potted
plants.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("display_case_3" ->
"display case"). The primitives and the SDF writing are the office generator's.
Run: python3 data/worlds/museum_models/make_museum.py > data/worlds/museum.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, plant)

W, D, H = 22.0, 16.0, 3.4  # floor width (x), depth (y), wall height (galleries are tall)
T = 0.1                    # wall thickness
YS = 6.0                   # the wall between the south rooms and the galleries
XE, XC = 8.0, 14.0         # south: entrance hall | gift shop | cafe
XG1, XG2 = 9.0, 15.0       # north: painting gallery | sculpture hall | artefact gallery
WC_X, WC_Y = 19.2, 3.5     # the toilets: the cafe's south-east corner (x > WC_X, y < WC_Y)
LINTEL = 2.6               # the top of the openings between rooms

MAIN_ENTRANCE = (3.4, 5.2)   # x, south wall
HALL_TO_GALLERY = (2.2, 4.8)  # x, wall y = YS
HALL_TO_SHOP = (2.0, 4.0)     # y, wall x = XE
SHOP_TO_SCULPTURE = (10.5, 12.5)  # x, wall y = YS
GALLERY_TO_CAFE = (16.5, 18.3)    # x, wall y = YS
PAINTING_TO_SCULPTURE = (10.0, 12.5)  # y, wall x = XG1
SCULPTURE_TO_ARTEFACT = (10.0, 12.5)  # y, wall x = XG2
TOILET_DOOR = (2.3, 3.3)     # y, wall x = WC_X
FIRE_EXIT = (10.4, 11.6)     # y, east wall

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "museum_floor": "0.62 0.55 0.46", "gallery_wall": "0.93 0.92 0.88", "partition": "0.86 0.85 0.82",
    "gold": "0.78 0.62 0.25", "dark_frame": "0.25 0.18 0.12", "canvas_sky": "0.45 0.6 0.82",
    "canvas_field": "0.42 0.55 0.25", "canvas_red": "0.7 0.18 0.15", "canvas_ochre": "0.8 0.6 0.25",
    "canvas_night": "0.12 0.15 0.3", "canvas_cream": "0.92 0.86 0.7", "canvas_teal": "0.2 0.5 0.5",
    "canvas_violet": "0.45 0.3 0.55", "brass": "0.8 0.65 0.3", "velvet": "0.55 0.06 0.1",
    "bronze": "0.45 0.32 0.18", "marble": "0.93 0.92 0.9", "plinth_white": "0.96 0.96 0.95",
    "oak": "0.55 0.4 0.25", "glass": "0.72 0.84 0.9", "terracotta": "0.72 0.38 0.22",
    "panel_board": "0.2 0.22 0.26", "text": "0.9 0.9 0.85", "camera_white": "0.9 0.9 0.9",
    "extinguisher_red": "0.8 0.08 0.06", "exit_green": "0.05 0.6 0.25", "steel": "0.7 0.72 0.74",
    "locker_blue": "0.25 0.38 0.55", "coat": "0.3 0.25 0.2", "coat2": "0.55 0.15 0.15",
    "counter_front": "0.35 0.28 0.22", "counter_top": "0.85 0.82 0.76", "book_red": "0.65 0.15 0.12",
    "book_blue": "0.15 0.25 0.55", "book_green": "0.2 0.45 0.25", "card": "0.95 0.9 0.8",
    "chair_black": "0.1 0.1 0.1", "table_top": "0.9 0.88 0.84", "porcelain": "0.97 0.97 0.97",
    "tile": "0.85 0.88 0.88", "mirror": "0.8 0.85 0.88", "fire_door": "0.55 0.58 0.6",
    "acrylic": "0.8 0.9 0.95", "umbrella": "0.1 0.2 0.35", "leaflet": "0.95 0.75 0.2",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned, along_x = base.turned, base.along_x


# ---- the things (local frames: x right, y forward = the side a visitor faces, z up) ----
def painting(w, h, palette, frame="gold"):
    """A framed painting hung on a wall (behind it at -y), centred on the model's height: the
    canvas in bands of colour with a figure in it, the picture looking along +y."""
    top, bottom, accent = palette
    return [box("frame", frame, 0, 0, 0, w + 0.14, 0.05, h + 0.14),
            box("sky", top, 0, 0.026, h * 0.2, w, 0.004, h * 0.6),
            box("ground", bottom, 0, 0.026, -h * 0.3, w, 0.004, h * 0.4),
            box("figure", accent, w * 0.15, 0.029, -h * 0.05, w * 0.18, 0.004, h * 0.45),
            box("label", "text", w / 2 + 0.25, 0.01, -h / 2 + 0.1, 0.12, 0.01, 0.08)]


def bench():
    """A backless gallery bench: an upholstered top on a dark frame, seats both sides."""
    return [box("seat", "velvet", 0, 0, 0.44, 1.6, 0.46, 0.08),
            box("rail", "dark_frame", 0, 0, 0.38, 1.5, 0.4, 0.04)] + legs("dark_frame", 0.72, 0.18, 0.38, 0.05)


def rope_barrier(length, posts=2):
    """Brass stanchions on round bases with a red velvet rope between them, along x."""
    v = []
    for i in range(posts):
        x = -length / 2 + i * length / (posts - 1)
        v += [cyl(f"base{i}", "brass", x, 0, 0.015, 0.15, 0.03),
              cyl(f"post{i}", "brass", x, 0, 0.48, 0.025, 0.93),
              sph(f"knob{i}", "brass", x, 0, 0.96, 0.045)]
    for i in range(posts - 1):
        x0 = -length / 2 + i * length / (posts - 1)
        seg = length / (posts - 1)
        v.append(along_x(cyl(f"rope{i}", "velvet", x0 + seg / 2, 0, 0.86, 0.02, seg)))
    return v


def information_panel():
    """A freestanding information panel: a slanted board of text on a post, read from +y."""
    return [box("foot", "panel_board", 0, 0, 0.02, 0.5, 0.35, 0.04),
            box("post", "panel_board", 0, 0, 0.55, 0.08, 0.06, 1.05),
            turned(box("board", "panel_board", 0, 0.02, 1.2, 0.7, 0.03, 0.55), "-0.35 0 0"),
            turned(box("text", "text", 0, 0.04, 1.22, 0.6, 0.004, 0.42), "-0.35 0 0")]


def security_camera():
    """A dome-less CCTV camera on a wall bracket (the wall behind at -y), tilted down into the room."""
    return [box("plate", "camera_white", 0, -0.02, 0, 0.1, 0.02, 0.14),
            box("arm", "camera_white", 0, 0.08, 0, 0.04, 0.18, 0.04),
            turned(box("body", "camera_white", 0, 0.2, -0.05, 0.11, 0.26, 0.11), "-0.5 0 0"),
            turned(box("lens", "chair_black", 0, 0.33, -0.12, 0.07, 0.02, 0.07), "-0.5 0 0")]


def fire_extinguisher():
    """A red extinguisher on its wall bracket (the wall behind at -y)."""
    return [box("bracket", "dark_metal", 0, -0.08, 0.85, 0.1, 0.02, 0.3),
            cyl("body", "extinguisher_red", 0, 0, 0.8, 0.08, 0.5),
            sph("shoulder", "extinguisher_red", 0, 0, 1.05, 0.08),
            cyl("head", "black", 0, 0, 1.15, 0.025, 0.08),
            box("handle", "black", 0, 0.04, 1.19, 0.03, 0.12, 0.02),
            turned(cyl("hose", "black", 0.07, 0.03, 1.0, 0.012, 0.3), "0 0.3 0")]


def plinth(w, h):
    """A white plinth for a sculpture: a square block with a dark plinth-skirting."""
    return [box("block", "plinth_white", 0, 0, h / 2, w, w, h),
            box("skirting", "dark_frame", 0, 0, 0.03, w + 0.02, w + 0.02, 0.06)]


def figure_sculpture():
    """A standing bronze figure, about 1.4 m, on its own small base (set on a plinth)."""
    return [box("base", "bronze", 0, 0, 0.03, 0.4, 0.3, 0.06),
            cyl("leg_l", "bronze", -0.08, 0, 0.42, 0.06, 0.74),
            cyl("leg_r", "bronze", 0.08, 0.02, 0.42, 0.06, 0.74),
            box("torso", "bronze", 0, 0, 1.04, 0.34, 0.2, 0.52),
            turned(cyl("arm_l", "bronze", -0.22, 0, 1.02, 0.045, 0.55), "0 -0.25 0"),
            turned(cyl("arm_r", "bronze", 0.24, 0.05, 1.14, 0.045, 0.55), "0.4 0.5 0"),
            cyl("neck", "bronze", 0, 0, 1.34, 0.04, 0.08),
            sph("head", "bronze", 0, 0, 1.46, 0.12)]


def abstract_sculpture(scale=1.0, c="marble"):
    """An abstract piece: rounded masses stacked and leaning, about 1.2 m times scale."""
    s = scale
    return [sph("mass0", c, 0, 0, 0.28 * s, 0.3 * s),
            turned(box("bridge", c, 0.08 * s, 0, 0.62 * s, 0.22 * s, 0.22 * s, 0.5 * s), "0 0.35 0"),
            sph("mass1", c, 0.16 * s, 0.03 * s, 0.9 * s, 0.22 * s),
            turned(cyl("spire", c, 0.1 * s, 0, 1.18 * s, 0.06 * s, 0.4 * s), "0 -0.3 0"),
            sph("tip", c, 0.04 * s, 0, 1.38 * s, 0.08 * s)]


def bust():
    """A marble portrait bust: shoulders, neck and head on a round socle."""
    return [cyl("socle", "marble", 0, 0, 0.05, 0.12, 0.1),
            box("shoulders", "marble", 0, 0, 0.2, 0.42, 0.22, 0.2),
            cyl("neck", "marble", 0, 0, 0.34, 0.06, 0.1),
            sph("head", "marble", 0, 0.01, 0.5, 0.13),
            sph("nose", "marble", 0, 0.13, 0.49, 0.03)]


def display_case(w=1.2, d=0.6):
    """A museum vitrine: an oak cabinet with a glass hood (four panes and a lid) over small
    finds (pots and a bowl); people look in from every side."""
    hz, gh = 0.88, 0.5  # the cabinet's top, the hood's height
    v = [box("cabinet", "oak", 0, 0, hz / 2, w, d, hz),
         box("deck", "canvas_cream", 0, 0, hz + 0.01, w - 0.04, d - 0.04, 0.02),
         box("pane_n", "glass", 0, d / 2 - 0.005, hz + gh / 2, w, 0.01, gh),
         box("pane_s", "glass", 0, -d / 2 + 0.005, hz + gh / 2, w, 0.01, gh),
         box("pane_w", "glass", -w / 2 + 0.005, 0, hz + gh / 2, 0.01, d, gh),
         box("pane_e", "glass", w / 2 - 0.005, 0, hz + gh / 2, 0.01, d, gh),
         box("lid", "glass", 0, 0, hz + gh, w, d, 0.01),
         box("edge_n", "steel", 0, d / 2, hz + gh, w, 0.02, 0.02),
         box("edge_s", "steel", 0, -d / 2, hz + gh, w, 0.02, 0.02)]
    v += [cyl("pot0", "terracotta", -w * 0.28, 0, hz + 0.12, 0.08, 0.22),
          sph("pot1", "terracotta", 0, 0.05, hz + 0.1, 0.09),
          cyl("bowl", "bronze", w * 0.28, -0.05, hz + 0.05, 0.1, 0.06),
          box("card", "text", 0, -d / 2 + 0.08, hz + 0.03, 0.1, 0.06, 0.01)]
    return v


def wall_case(w=1.8, d=0.5, h=2.1):
    """A tall glass wall case against a wall (behind it at -y): three glass shelves of objects."""
    v = [box("back", "oak", 0, -d / 2 + 0.02, h / 2, w, 0.04, h),
         box("plinth", "oak", 0, 0, 0.2, w, d, 0.4),
         box("top", "oak", 0, 0, h - 0.05, w, d, 0.1),
         box("side_l", "oak", -w / 2 + 0.02, 0, h / 2, 0.04, d, h),
         box("side_r", "oak", w / 2 - 0.02, 0, h / 2, 0.04, d, h),
         box("front", "glass", 0, d / 2 - 0.01, 1.2, w - 0.08, 0.01, 1.5)]
    for i in range(3):
        z = 0.42 + 0.5 * i
        v.append(box(f"shelf{i}", "glass", 0, 0, z, w - 0.08, d - 0.06, 0.01))
        v += [cyl(f"obj{i}_{k}", ("terracotta", "bronze", "marble")[(i + k) % 3], -0.6 + 0.4 * k, 0, z + 0.12,
                  0.07, 0.22) for k in range(4)]
    return v


def ticket_desk(length=2.2, depth=0.7):
    """The ticket and information counter: a tall front to the visitors (+y), the work top behind
    it, a card terminal and a ticket printer on the ledge."""
    return [box("front", "counter_front", 0, depth / 2 - 0.03, 0.55, length, 0.06, 1.1),
            box("ledge", "counter_top", 0, depth / 2 - 0.1, 1.12, length + 0.05, 0.25, 0.04),
            box("work_top", "counter_top", 0, -0.05, 0.75, length, depth - 0.1, 0.04),
            box("side_l", "counter_front", -length / 2, 0, 0.55, 0.04, depth, 1.1),
            box("side_r", "counter_front", length / 2, 0, 0.55, 0.04, depth, 1.1),
            box("terminal", "chair_black", 0.5, depth / 2 - 0.1, 1.17, 0.08, 0.14, 0.05),
            box("ticket_printer", "grey_plastic", -0.4, -0.1, 0.85, 0.2, 0.25, 0.16),
            box("sign", "book_blue", 0, depth / 2 - 0.1, 1.3, 0.5, 0.02, 0.3)]


def coat_rack():
    """A freestanding coat stand: round foot, pole, hooks at the top, two coats hung on it."""
    v = [cyl("foot", "dark_metal", 0, 0, 0.02, 0.25, 0.04),
         cyl("pole", "dark_metal", 0, 0, 0.9, 0.025, 1.76),
         sph("cap", "dark_metal", 0, 0, 1.8, 0.04)]
    v += [box(f"hook{i}", "dark_metal", dx * 0.09, dy * 0.09, 1.68, 0.18 if dx else 0.02, 0.18 if dy else 0.02, 0.02)
          for i, (dx, dy) in enumerate(((1, 0), (-1, 0), (0, 1), (0, -1)))]
    return v + [box("coat0", "coat", 0.16, 0, 1.25, 0.12, 0.45, 0.8),
                box("coat1", "coat2", -0.14, 0.05, 1.3, 0.1, 0.4, 0.7)]


def locker_bank(cols=3, rows=4):
    """A bank of visitors' lockers against a wall (behind at -y): doors in a grid, each with a key."""
    w, d, h = 0.4 * cols, 0.5, 1.8
    v = [box("body", "locker_blue", 0, 0, h / 2, w, d, h)]
    for c in range(1, cols):
        v.append(box(f"seam_v{c}", "dark_metal", -w / 2 + 0.4 * c, d / 2 + 0.002, h / 2, 0.01, 0.004, h))
    for r in range(1, rows):
        v.append(box(f"seam_h{r}", "dark_metal", 0, d / 2 + 0.002, h * r / rows, w, 0.004, 0.01))
    v += [box(f"key{c}_{r}", "brass", -w / 2 + 0.4 * c + 0.32, d / 2 + 0.01, h * (r + 0.5) / rows, 0.03, 0.02, 0.05)
          for c in range(cols) for r in range(rows)]
    return v


def umbrella_stand():
    """A tall metal pot for wet umbrellas, two of them in it."""
    return [cyl("pot", "dark_metal", 0, 0, 0.28, 0.14, 0.56),
            cyl("umbrella0", "umbrella", -0.04, 0, 0.6, 0.03, 0.5),
            turned(cyl("umbrella1", "velvet", 0.05, 0.02, 0.58, 0.03, 0.48), "0.15 0 0"),
            sph("handle0", "oak", -0.04, 0, 0.88, 0.03)]


def brochure_rack():
    """A slim floor stand of four tiers of leaflets and gallery guides, facing +y."""
    v = [box("back", "steel", 0, -0.1, 0.75, 0.5, 0.02, 1.5),
         box("foot", "steel", 0, 0, 0.02, 0.5, 0.3, 0.04)]
    for i in range(4):
        z = 0.55 + 0.27 * i
        v += [box(f"tray{i}", "acrylic", 0, -0.04, z, 0.48, 0.1, 0.02),
              box(f"leaflets{i}_0", ("leaflet", "book_blue", "canvas_red", "card")[i], -0.12, -0.05, z + 0.1,
                  0.2, 0.02, 0.2),
              box(f"leaflets{i}_1", ("card", "leaflet", "book_green", "book_blue")[i], 0.12, -0.05, z + 0.1,
                  0.2, 0.02, 0.2)]
    return v


def donation_box():
    """A clear acrylic donation box with a coin slot, on a grey pedestal, notes and coins inside."""
    return [box("pedestal", "grey_plastic", 0, 0, 0.45, 0.3, 0.3, 0.9),
            box("box", "acrylic", 0, 0, 1.08, 0.34, 0.34, 0.36),
            box("slot", "chair_black", 0, 0, 1.265, 0.12, 0.02, 0.01),
            box("money", "canvas_field", 0, 0, 0.95, 0.28, 0.28, 0.08)]


def shop_shelf():
    """A gift-shop shelving unit against a wall (behind at -y): four shelves of books, boxed
    gifts and mugs."""
    v = [box("back", "oak", 0, -0.18, 0.9, 1.2, 0.03, 1.8),
         box("side_l", "oak", -0.59, 0, 0.9, 0.02, 0.4, 1.8),
         box("side_r", "oak", 0.59, 0, 0.9, 0.02, 0.4, 1.8)]
    colours = ("book_red", "book_blue", "book_green", "card", "canvas_ochre")
    for i in range(4):
        z = 0.1 + 0.45 * i
        v.append(box(f"shelf{i}", "oak", 0, 0, z, 1.18, 0.38, 0.02))
        v += [box(f"item{i}_{k}", colours[(i + k) % 5], -0.45 + 0.3 * k, 0, z + 0.13, 0.24, 0.28, 0.24)
              for k in range(4)]
    return v


def shop_counter(length=1.6):
    """The shop's sales counter: a closed front to the customers (+y), the top over it."""
    return [box("body", "counter_front", 0, 0, 0.46, length, 0.6, 0.92),
            box("top", "counter_top", 0, 0, 0.94, length + 0.05, 0.65, 0.04),
            box("bag_shelf", "oak", 0, -0.32, 0.5, length - 0.1, 0.04, 0.02)]


def cash_register():
    """A till on a counter: the drawer, the keypad and a tilted screen facing the cashier (-y),
    a customer display facing +y."""
    return [box("drawer", "chair_black", 0, 0, 0.05, 0.4, 0.38, 0.1),
            box("keypad", "grey_plastic", 0, -0.08, 0.12, 0.3, 0.18, 0.04),
            turned(box("screen", "chair_black", 0, 0.08, 0.24, 0.3, 0.02, 0.2), "0.3 0 0"),
            box("customer_display", "text", 0, 0.15, 0.28, 0.16, 0.01, 0.06)]


def postcard_stand():
    """A revolving postcard spinner: a cross foot, the pole, four faces of card pockets."""
    v = [box("foot_x", "dark_metal", 0, 0, 0.02, 0.55, 0.06, 0.04),
         box("foot_y", "dark_metal", 0, 0, 0.02, 0.06, 0.55, 0.04),
         cyl("pole", "dark_metal", 0, 0, 0.85, 0.02, 1.7),
         box("core", "steel", 0, 0, 1.1, 0.3, 0.3, 1.1)]
    colours = ("canvas_sky", "card", "canvas_red", "canvas_field", "canvas_ochre", "canvas_teal")
    for r in range(4):
        z = 0.7 + 0.27 * r
        for k, (dx, dy, sx, sy) in enumerate(((0, 0.16, 0.28, 0.01), (0, -0.16, 0.28, 0.01),
                                              (0.16, 0, 0.01, 0.28), (-0.16, 0, 0.01, 0.28))):
            v.append(box(f"cards{r}_{k}", colours[(r + k) % 6], dx, dy, z, sx, sy, 0.2))
    return v


def cafe_table():
    """A round bistro table on a pedestal."""
    return [cyl("top", "table_top", 0, 0, 0.74, 0.38, 0.03),
            cyl("pedestal", "dark_metal", 0, 0, 0.37, 0.035, 0.72),
            cyl("foot", "dark_metal", 0, 0, 0.015, 0.24, 0.03)]


def cafe_chair():
    """A light bistro chair, its back at -y (the person faces +y)."""
    return [box("seat", "oak", 0, 0, 0.45, 0.42, 0.42, 0.04),
            box("back", "oak", 0, -0.2, 0.7, 0.4, 0.03, 0.45)] + legs("chair_black", 0.18, 0.18, 0.43, 0.025)


def cafe_counter(length=2.0):
    """The cafe's serving counter: front to the customers (+y), a glass cake display at one end."""
    return [box("body", "counter_front", 0, 0, 0.5, length, 0.6, 1.0),
            box("top", "counter_top", 0, 0, 1.01, length + 0.05, 0.65, 0.03),
            box("cake_display", "glass", -length / 2 + 0.35, 0.05, 1.2, 0.6, 0.45, 0.35),
            sph("cake", "canvas_ochre", -length / 2 + 0.35, 0.05, 1.1, 0.08)]


def coffee_machine():
    """An espresso machine standing on a counter, its group heads and drip tray at +y."""
    return [box("body", "steel", 0, 0, 0.24, 0.6, 0.45, 0.48),
            box("top_tray", "dark_metal", 0, 0, 0.5, 0.58, 0.4, 0.04),
            box("drip_tray", "dark_metal", 0, 0.2, 0.03, 0.5, 0.12, 0.02),
            cyl("group0", "chair_black", -0.14, 0.25, 0.3, 0.04, 0.08),
            cyl("group1", "chair_black", 0.14, 0.25, 0.3, 0.04, 0.08),
            sph("cup", "porcelain", 0.14, 0.22, 0.08, 0.04)]


def waste_bin():
    return [cyl("body", "dark_metal", 0, 0, 0.32, 0.18, 0.64), cyl("lid", "steel", 0, 0, 0.66, 0.19, 0.04)]


def toilet():
    """A toilet: the cistern against the wall (-y), the bowl and seat in front of it."""
    return [box("cistern", "porcelain", 0, -0.22, 0.62, 0.42, 0.18, 0.4),
            cyl("bowl", "porcelain", 0, 0.05, 0.2, 0.19, 0.4),
            cyl("seat", "porcelain", 0, 0.06, 0.41, 0.21, 0.03),
            box("flush", "steel", 0, -0.22, 0.83, 0.1, 0.06, 0.02)]


def sink():
    """A wall-hung wash basin (the wall behind at -y) with its tap."""
    return [box("basin", "porcelain", 0, 0.05, 0.8, 0.5, 0.42, 0.15),
            box("bowl", "tile", 0, 0.07, 0.86, 0.38, 0.3, 0.04),
            cyl("tap", "steel", 0, -0.1, 0.95, 0.02, 0.16),
            box("spout", "steel", 0, -0.04, 1.02, 0.03, 0.12, 0.02),
            cyl("trap", "steel", 0, -0.05, 0.55, 0.03, 0.35)]


def hand_dryer():
    """A wall-mounted hand dryer (the wall behind at -y), its nozzle pointing down."""
    return [box("body", "porcelain", 0, 0.08, 1.2, 0.28, 0.16, 0.3),
            box("nozzle", "steel", 0, 0.1, 1.03, 0.08, 0.08, 0.05)]


def mirror(w=0.6, h=0.8):
    """A washroom mirror on the wall (behind at -y)."""
    return [box("frame", "steel", 0, 0, 0, w + 0.04, 0.02, h + 0.04),
            box("glass", "mirror", 0, 0.011, 0, w, 0.004, h)]


def fire_exit_door(width=1.2):
    """The fire exit: two closed steel leaves in the opening with push bars, seen from +y."""
    half = width / 2
    return [box("leaf_l", "fire_door", -half / 2, 0, 1.05, half - 0.01, 0.05, 2.1),
            box("leaf_r", "fire_door", half / 2, 0, 1.05, half - 0.01, 0.05, 2.1),
            box("bar_l", "steel", -half / 2, 0.05, 1.0, half - 0.12, 0.04, 0.05),
            box("bar_r", "steel", half / 2, 0.05, 1.0, half - 0.12, 0.04, 0.05),
            box("stripe", "exit_green", 0, 0.027, 1.6, width - 0.1, 0.004, 0.12)]


def exit_sign():
    """The green illuminated exit sign over a door (the wall behind at -y): the running man."""
    return [box("body", "exit_green", 0, 0, 0, 0.42, 0.05, 0.16),
            box("man", "white", -0.1, 0.026, 0, 0.06, 0.004, 0.11),
            box("arrow", "white", 0.08, 0.026, 0, 0.16, 0.004, 0.04)]


def walls():
    """The outer walls with the main entrance and the fire exit; the wall between the south
    rooms and the galleries with its openings; the partitions between rooms; the toilets'
    corner room and the wall between its two cubicles."""
    v, wall = base.wall_builder(H, T)
    e0, e1 = MAIN_ENTRANCE
    wall(0, 0, e0, 0); wall(e1, 0, W, 0); wall(e0, 0, e1, 0, 2.3, H)
    wall(0, D, W, D); wall(0, 0, 0, D)
    f0, f1 = FIRE_EXIT
    wall(W, 0, W, f0); wall(W, f1, W, D); wall(W, f0, W, f1, 2.2, H)

    def with_openings(fixed, along, lo, hi, openings, c):
        """A wall along x (along = 'x', y = fixed) or y with the openings (lo..hi) in it."""
        cut = lo
        for a, b in openings:
            if along == "x":
                wall(cut, fixed, a, fixed, c=c); wall(a, fixed, b, fixed, LINTEL, H, c=c)
            else:
                wall(fixed, cut, fixed, a, c=c); wall(fixed, a, fixed, b, LINTEL, H, c=c)
            cut = b
        if along == "x": wall(cut, fixed, hi, fixed, c=c)
        else: wall(fixed, cut, fixed, hi, c=c)

    with_openings(YS, "x", 0, W, (HALL_TO_GALLERY, SHOP_TO_SCULPTURE, GALLERY_TO_CAFE), "gallery_wall")
    with_openings(XE, "y", 0, YS, (HALL_TO_SHOP,), "partition")
    wall(XC, 0, XC, YS, c="partition")  # the gift shop and the cafe: no way through
    with_openings(XG1, "y", YS, D, (PAINTING_TO_SCULPTURE,), "gallery_wall")
    with_openings(XG2, "y", YS, D, (SCULPTURE_TO_ARTEFACT,), "gallery_wall")
    # the toilets: a corner room with its door in the west partition, two cubicles on the east wall
    with_openings(WC_X, "y", 0, WC_Y, (TOILET_DOOR,), "partition")
    wall(WC_X, WC_Y, W, WC_Y, c="partition")
    wall(20.95, 1.35, W, 1.35, 0, 2.0, c="partition")
    return v


def entrance_hall(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    e0, e1 = MAIN_ENTRANCE
    add("door_1", (e0 + 0.04, 0.47, 0, WEST), base.door())  # two leaves swung open into the hall
    add("door_2", (e1 - 0.04, 0.47, 0, WEST), base.door())
    add("window_1", (1.6, T / 2 + 0.02, 1.6, N), base.window())
    # the ticket desk north-east of the entrance, its front to the south, the clerk behind it
    add("ticket_desk", (6.5, 4.5, 0, S), ticket_desk())
    add("office_chair", (6.5, 5.3, 0, S), base.office_chair())
    add("brochure_rack", (7.3, T / 2 + 0.16, 0, N), brochure_rack())
    add("donation_box", (6.0, 1.4, 0, N), donation_box())
    add("potted_plant_1", (7.55, 1.0, 0, N), base.plant())
    add("potted_plant_2", (2.9, 0.45, 0, N), base.plant())
    add("umbrella_stand", (5.65, 0.3, 0, N), umbrella_stand())
    # the cloakroom corner on the west wall
    add("coat_rack_1", (0.45, 1.2, 0, E), coat_rack())
    add("coat_rack_2", (0.45, 2.1, 0, E), coat_rack())
    add("locker_1", (T / 2 + 0.25, 3.3, 0, E), locker_bank())
    add("locker_2", (T / 2 + 0.25, 4.55, 0, E), locker_bank())
    # a featured object in a case, and the floor plan by the gallery opening
    add("display_case_1", (2.2, 3.0, 0, E), display_case())
    add("information_panel_1", (1.8, 5.4, 0, S), information_panel())
    add("fire_extinguisher_1", (1.3, YS - T / 2 - 0.1, 0, S), fire_extinguisher())
    add("security_camera_1", (XE - T / 2 - 0.12, T / 2 + 0.05, 3.05, 0.7854), security_camera())


def gift_shop(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("window_2", (9.4, T / 2 + 0.02, 1.6, N), base.window())
    for i, y in enumerate((1.0, 2.35, 3.7), 1):
        add(f"shop_shelf_{i}", (XC - T / 2 - 0.2, y, 0, WEST), shop_shelf())
    add("shop_shelf_4", (11.0, T / 2 + 0.2, 0, N), shop_shelf())
    add("shop_shelf_5", (12.3, T / 2 + 0.2, 0, N), shop_shelf())
    add("shop_counter", (9.6, 5.15, 0, S), shop_counter())
    add("cash_register", (9.35, 5.2, 0.96, S), cash_register())
    add("postcard_stand_1", (10.9, 2.6, 0, N), postcard_stand())
    add("postcard_stand_2", (12.0, 3.6, 0, N), postcard_stand())


def cafe(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("window_3", (15.6, T / 2 + 0.02, 1.6, N), base.window())
    add("window_4", (18.1, T / 2 + 0.02, 1.6, N), base.window())
    n = 0
    for i, (x, y) in enumerate(((15.4, 1.3), (17.6, 1.3), (15.4, 3.7), (17.6, 3.7)), 1):
        add(f"cafe_table_{i}", (x, y, 0, N), cafe_table())
        for dx, yaw in ((-0.6, E), (0.6, WEST)):
            n += 1
            add(f"cafe_chair_{n}", (x + dx, y, 0, yaw), cafe_chair())
    add("cafe_counter", (20.7, 4.9, 0, S), cafe_counter())
    add("coffee_machine", (20.1, 4.95, 1.025, N), coffee_machine())
    add("waste_bin_1", (19.2, 5.6, 0, N), waste_bin())
    add("potted_plant_3", (14.45, 5.55, 0, N), base.plant())
    # the toilets
    _, t1 = TOILET_DOOR
    add("door_3", (WC_X + 0.47, t1 - 0.04, 0, N), base.door())  # hinged at the doorway's north side
    add("toilet_1", (W - T / 2 - 0.32, 0.68, 0, WEST), toilet())
    add("toilet_2", (W - T / 2 - 0.32, 2.1, 0, WEST), toilet())
    for i, x in enumerate((19.75, 20.45), 1):
        add(f"sink_{i}", (x, T / 2 + 0.01, 0, N), sink())
        add(f"mirror_{i}", (x, T / 2 + 0.02, 1.55, N), mirror(0.5, 0.7))
    add("hand_dryer", (WC_X + T / 2 + 0.01, 1.4, 0, E), hand_dryer())
    add("waste_bin_2", (WC_X + 0.27, 1.1, 0, N), waste_bin())


PALETTES = [("canvas_sky", "canvas_field", "canvas_red"), ("canvas_night", "canvas_ochre", "canvas_cream"),
            ("canvas_cream", "canvas_teal", "canvas_violet"), ("canvas_ochre", "canvas_red", "canvas_night"),
            ("canvas_teal", "canvas_cream", "canvas_ochre"), ("canvas_violet", "canvas_sky", "canvas_field")]


def painting_gallery(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    o = T / 2 + 0.03  # a picture's centre off the wall
    hung = [  # (x, y, z, yaw, width, height, frame)
        (o, 8.0, 1.6, E, 1.2, 0.9, "gold"), (o, 10.8, 1.7, E, 1.6, 1.1, "dark_frame"),
        (o, 13.8, 1.6, E, 1.0, 1.2, "gold"),
        (2.0, D - o, 1.6, S, 0.9, 0.7, "dark_frame"), (4.6, D - o, 1.8, S, 2.4, 1.6, "gold"),
        (7.2, D - o, 1.6, S, 0.9, 0.7, "dark_frame"),
        (XG1 - o, 7.9, 1.6, WEST, 1.1, 0.8, "gold"), (XG1 - o, 14.4, 1.6, WEST, 1.3, 1.0, "gold"),
        (1.0, YS + o, 1.6, N, 0.8, 1.0, "dark_frame"), (6.8, YS + o, 1.6, N, 1.4, 1.0, "gold"),
    ]
    for i, (x, y, z, yaw, w, h, fr) in enumerate(hung, 1):
        add(f"painting_{i}", (x, y, z, yaw), painting(w, h, PALETTES[i % len(PALETTES)], fr))
    # the large painting on the north wall is roped off; its panel beside the rope
    add("rope_barrier_1", (4.6, D - 0.9, 0, N), rope_barrier(3.0, 3))
    add("information_panel_2", (6.6, D - 0.9, 0, S), information_panel())
    add("information_panel_3", (1.0, 12.3, 0, E), information_panel())
    add("bench_1", (4.6, 11.6, 0, N), bench())
    add("bench_2", (4.6, 8.6, 0, N), bench())
    add("fire_extinguisher_2", (XG1 - T / 2 - 0.1, 9.3, 0, WEST), fire_extinguisher())
    add("security_camera_2", (T / 2 + 0.05, D - T / 2 - 0.12, 3.05, -2.3562), security_camera())
    add("potted_plant_4", (8.5, 6.5, 0, N), base.plant())


def sculpture_hall(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the large abstract piece in the middle on a low plinth, roped off on its south side
    add("plinth_1", (12.0, 12.9, 0, N), plinth(1.2, 0.4))
    add("sculpture_1", (12.0, 12.9, 0.4, N), abstract_sculpture(1.5, "marble"))
    add("rope_barrier_2", (12.0, 11.8, 0, N), rope_barrier(2.0, 2))
    add("bench_3", (12.0, 9.9, 0, N), bench())
    # bronze figures on plinths in the south corners, busts on tall plinths in the north corners
    add("plinth_2", (9.9, 7.0, 0, N), plinth(0.6, 0.9))
    add("sculpture_2", (9.9, 7.0, 0.9, N), figure_sculpture())
    add("plinth_3", (14.1, 7.0, 0, N), plinth(0.6, 0.9))
    add("sculpture_3", (14.1, 7.0, 0.9, N), abstract_sculpture(0.8, "bronze"))
    add("plinth_4", (9.8, 15.2, 0, S), plinth(0.45, 1.2))
    add("bust_1", (9.8, 15.2, 1.2, S), bust())
    add("plinth_5", (14.2, 15.2, 0, S), plinth(0.45, 1.2))
    add("bust_2", (14.2, 15.2, 1.2, S), bust())
    add("information_panel_4", (9.9, 7.8, 0, N), information_panel())
    add("information_panel_5", (13.7, 12.2, 0, S), information_panel())
    add("security_camera_3", (XG2 - T / 2 - 0.05, D - T / 2 - 0.12, 3.05, 2.3562), security_camera())


def artefact_gallery(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    for i, (x, y) in enumerate(((16.9, 8.6), (19.6, 8.6), (16.9, 13.4), (19.6, 13.4)), 2):
        add(f"display_case_{i}", (x, y, 0, N), display_case())
    add("display_case_6", (18.3, D - T / 2 - 0.25, 0, S), wall_case())  # the tall wall case
    add("information_panel_6", (18.25, 8.6, 0, N), information_panel())
    add("bench_4", (17.6, 11.0, 0, N), bench())
    f0, f1 = FIRE_EXIT
    add("fire_exit_door", (W - 0.03, (f0 + f1) / 2, 0, WEST), fire_exit_door(f1 - f0))
    add("exit_sign", (W - T / 2 - 0.03, (f0 + f1) / 2, 2.4, WEST), exit_sign())
    add("fire_extinguisher_3", (W - T / 2 - 0.1, f1 + 0.6, 0, WEST), fire_extinguisher())
    add("security_camera_4", (W - T / 2 - 0.05, YS + T / 2 + 0.12, 3.05, 0.7854), security_camera())
    add("waste_bin_3", (15.5, 6.4, 0, N), waste_bin())


def main():
    out = base.shell(walls(), "floor_museum", "museum_floor", W, D, H)
    entrance_hall(out)
    gift_shop(out)
    cafe(out)
    painting_gallery(out)
    sculpture_hall(out)
    artefact_gallery(out)
    lights = [base.point_light(name, x, y, 3.15, "0.8 0.79 0.76")
              for name, x, y in (("light_entrance", 4.0, 2.8), ("light_shop", 11.0, 3.0),
                                 ("light_cafe", 16.7, 3.0), ("light_toilets", 20.7, 1.8),
                                 ("light_paintings_s", 4.5, 8.5), ("light_paintings_n", 4.5, 13.5),
                                 ("light_sculpture_s", 12.0, 8.5), ("light_sculpture_n", 12.0, 13.5),
                                 ("light_artefacts_s", 18.5, 8.5), ("light_artefacts_n", 18.5, 13.5))]
    print(base.world_sdf("semsplat_museum", """The semsplat museum: a small museum of 22 m x 16 m (south, west to east: the entrance hall
     with the ticket desk and a cloakroom corner, the gift shop, the cafe with the toilets in its
     corner; north: the painting gallery, the sculpture hall and the artefact gallery with the
     fire exit) for measuring on a world nobody tuned on. Generated by
     museum_models/make_museum.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
