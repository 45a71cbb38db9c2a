#!/usr/bin/env python3
"""Writes the bundled house: data/worlds/house.world and the models it includes
(data/worlds/house_models/<name>/model.sdf + model.config). Everything is built from SDF
primitives with colours; surface detail comes from semsplat's procedural patterns, chosen by
the material script / visual names (wood, fabric, tiles, carpet, metal, glass). Re-run after
editing: /usr/bin/python3 data/worlds/house_models/make_house.py"""
import math, os, random, re

HERE = os.path.dirname(os.path.abspath(__file__))
WORLD = os.path.join(os.path.dirname(HERE), "house.world")
rnd = random.Random(7)


def f(v):
    return " ".join("%.4g" % x for x in v)


def mat(rgb, script=None):
    s = "<script><name>%s</name></script>" % script if script else ""
    return ("<material>%s<ambient>%s 1</ambient><diffuse>%s 1</diffuse>"
            "<specular>0.1 0.1 0.1 1</specular></material>" % (s, f(rgb), f(rgb)))


def box(name, pos, size, rgb, rpy=(0, 0, 0), script=None):
    return ('<visual name="%s"><pose>%s %s</pose><geometry><box><size>%s</size></box></geometry>%s</visual>'
            % (name, f(pos), f(rpy), f(size), mat(rgb, script)))


def cyl(name, pos, r, length, rgb, rpy=(0, 0, 0), script=None):
    return ('<visual name="%s"><pose>%s %s</pose><geometry><cylinder><radius>%g</radius><length>%g</length>'
            '</cylinder></geometry>%s</visual>' % (name, f(pos), f(rpy), r, length, mat(rgb, script)))


def sph(name, pos, r, rgb, script=None):
    return ('<visual name="%s"><pose>%s 0 0 0</pose><geometry><sphere><radius>%g</radius></sphere></geometry>%s</visual>'
            % (name, f(pos), r, mat(rgb, script)))


def collisions(visuals):
    """The same shapes as <collision>s, so the house also works in Gazebo with a robot in it."""
    out = []
    for v in visuals:
        c = re.sub(r"<material>.*?</material>", "", v).replace("<visual ", "<collision ").replace("</visual>", "</collision>")
        out.append(c.replace('<collision name="', '<collision name="c_', 1))
    return out


def link(visuals, name="link"):
    return '<link name="%s">%s</link>' % (name, "\n".join(visuals + collisions(visuals)))


def model_xml(name, links, pose=None, static=True):
    p = "<pose>%s</pose>" % f(pose) if pose else ""
    return '<model name="%s">%s<static>%d</static>\n%s\n</model>' % (name, p, int(static), "\n".join(links))


def write_model(name, body, description):
    d = os.path.join(HERE, name)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "model.sdf"), "w") as fh:
        fh.write('<?xml version="1.0"?>\n<sdf version="1.6">\n%s\n</sdf>\n' % model_xml(name, [body]))
    with open(os.path.join(d, "model.config"), "w") as fh:
        fh.write('<?xml version="1.0"?>\n<model>\n  <name>%s</name>\n  <version>1.0</version>\n'
                 '  <sdf version="1.6">model.sdf</sdf>\n  <author><name>semsplat</name></author>\n'
                 '  <description>%s</description>\n</model>\n' % (name, description))


# Models: origin at the centre of the footprint on the floor, front facing +x.
STEEL = (0.72, 0.73, 0.75)
HANDLE = (0.55, 0.56, 0.58)


def refrigerator():
    w, d, h = 0.8, 0.72, 1.85
    v = [box("enamel_body", (0, 0, h / 2), (d, w, h), (0.93, 0.94, 0.95), script="Gazebo/White")]
    # two doors (freezer on top) with a dark gap between, and long vertical handles
    v.append(box("enamel_door_fridge", (d / 2 + 0.02, 0, 0.62), (0.04, w - 0.02, 1.2), (0.9, 0.91, 0.93)))
    v.append(box("enamel_door_freezer", (d / 2 + 0.02, 0, 1.55), (0.04, w - 0.02, 0.56), (0.9, 0.91, 0.93)))
    v.append(box("gap", (d / 2 + 0.005, 0, 1.245), (0.03, w, 0.03), (0.15, 0.15, 0.16)))
    v.append(box("metal_handle_low", (d / 2 + 0.07, -w / 2 + 0.08, 0.85), (0.03, 0.03, 0.7), HANDLE))
    v.append(box("metal_handle_high", (d / 2 + 0.07, -w / 2 + 0.08, 1.5), (0.03, 0.03, 0.35), HANDLE))
    for y in (-w / 2 + 0.08,):
        for z0, z1 in ((0.52, 1.18), (1.35, 1.63)):
            for z in (z0, z1):
                v.append(box("metal_bracket", (d / 2 + 0.055, y, z), (0.05, 0.025, 0.025), HANDLE))
    v.append(box("logo", (d / 2 + 0.042, 0.12, 1.72), (0.005, 0.12, 0.03), (0.2, 0.2, 0.22)))
    v.append(box("metal_kick", (d / 2 - 0.02, 0, 0.03), (0.04, w - 0.04, 0.06), (0.2, 0.2, 0.2)))
    write_model("refrigerator", link(v), "A white two-door refrigerator with freezer on top.")


def cabinet(v, w, d, h, body_rgb, top_rgb, doors=2, drawers=True, prefix="wood"):
    v.append(box(prefix + "_cabinet", (0, 0, (h - 0.04) / 2 + 0.05), (d - 0.03, w, h - 0.04 - 0.1), body_rgb))
    v.append(box("kick", (-0.02, 0, 0.05), (d - 0.08, w - 0.02, 0.1), (0.12, 0.12, 0.12)))
    v.append(box("stone_countertop", (0.01, 0, h - 0.02), (d + 0.02, w + 0.01, 0.04), top_rgb))
    fw = (w - 0.02) / doors
    for i in range(doors):
        y = -w / 2 + 0.01 + fw * (i + 0.5)
        dz = 0.38 if drawers else 0.44
        v.append(box(prefix + "_door", (d / 2 - 0.005, y, 0.1 + dz), (0.02, fw - 0.015, 2 * dz - 0.06),
                     tuple(min(1, c * 1.06) for c in body_rgb)))
        hy = y + (fw / 2 - 0.06) * (1 if i % 2 == 0 else -1)
        v.append(box("metal_handle", (d / 2 + 0.02, hy, 0.1 + 2 * dz - 0.15), (0.02, 0.015, 0.12), HANDLE))
        if drawers:
            v.append(box(prefix + "_drawer", (d / 2 - 0.005, y, h - 0.15), (0.02, fw - 0.015, 0.14),
                         tuple(min(1, c * 1.06) for c in body_rgb)))
            v.append(box("metal_pull", (d / 2 + 0.02, y, h - 0.15), (0.02, 0.14, 0.015), HANDLE))


SAGE = (0.42, 0.58, 0.5)
GRANITE = (0.22, 0.22, 0.24)


def kitchen_counter():
    v = []
    cabinet(v, 1.2, 0.6, 0.92, SAGE, GRANITE, doors=2, prefix="painted")
    # things on the counter: a chopping board and a red kettle
    v.append(box("wood_board", (0.02, -0.25, 0.935), (0.3, 0.42, 0.025), (0.75, 0.55, 0.32)))
    v.append(cyl("metal_kettle", (-0.05, 0.3, 1.02), 0.09, 0.18, (0.8, 0.12, 0.1)))
    v.append(cyl("kettle_base", (-0.05, 0.3, 0.925), 0.1, 0.015, (0.1, 0.1, 0.1)))
    v.append(box("kettle_spout", (0.05, 0.3, 1.06), (0.08, 0.025, 0.025), (0.8, 0.12, 0.1), rpy=(0, -0.6, 0)))
    write_model("kitchen_counter", link(v), "Kitchen base cabinets (sage green) with a granite top.")


def sink():
    v = []
    cabinet(v, 1.0, 0.6, 0.92, SAGE, GRANITE, doors=2, drawers=False, prefix="painted")
    # steel basin set into the top: rim + dark inside
    v.append(box("metal_basin_rim", (0.03, 0, 0.925), (0.46, 0.7, 0.012), (0.78, 0.79, 0.8)))
    v.append(box("metal_basin", (0.03, 0, 0.932), (0.38, 0.6, 0.004), (0.42, 0.43, 0.45)))
    v.append(cyl("metal_drain", (0.03, 0, 0.935), 0.03, 0.004, (0.15, 0.15, 0.15)))
    # faucet: a post and a spout arching forward, two knobs
    v.append(cyl("chrome_faucet_post", (-0.22, 0, 1.07), 0.022, 0.3, (0.82, 0.83, 0.86)))
    v.append(box("chrome_faucet_spout", (-0.12, 0, 1.21), (0.22, 0.035, 0.035), (0.82, 0.83, 0.86)))
    v.append(cyl("chrome_faucet_tip", (-0.02, 0, 1.18), 0.018, 0.07, (0.82, 0.83, 0.86)))
    for y in (-0.12, 0.12):
        v.append(cyl("chrome_knob", (-0.22, y, 0.97), 0.025, 0.06, (0.82, 0.83, 0.86)))
    write_model("sink", link(v), "A kitchen sink cabinet with a steel basin and a chrome faucet.")


def stove():
    w, d, h = 0.7, 0.62, 0.92
    v = [box("metal_body", (0, 0, h / 2), (d, w, h), (0.8, 0.81, 0.83))]
    v.append(box("glass_cooktop", (0, 0, h + 0.01), (d, w, 0.02), (0.05, 0.05, 0.06)))
    for x in (-0.14, 0.14):
        for y in (-0.16, 0.16):
            v.append(cyl("burner_ring", (x, y, h + 0.021), 0.085 if x < 0 else 0.07, 0.003, (0.35, 0.1, 0.08)))
            v.append(cyl("burner_centre", (x, y, h + 0.023), 0.05 if x < 0 else 0.04, 0.003, (0.08, 0.08, 0.09)))
    # oven door with a dark window and a long bar handle; control strip with knobs
    v.append(box("metal_oven_door", (d / 2 + 0.015, 0, 0.42), (0.03, w - 0.04, 0.6), (0.78, 0.79, 0.81)))
    v.append(box("glass_oven_window", (d / 2 + 0.031, 0, 0.42), (0.003, w - 0.2, 0.3), (0.08, 0.07, 0.07)))
    v.append(cyl("metal_oven_handle", (d / 2 + 0.06, 0, 0.68), 0.012, w - 0.12, HANDLE, rpy=(math.pi / 2, 0, 0)))
    v.append(box("control_panel", (d / 2 + 0.01, 0, 0.83), (0.02, w - 0.04, 0.1), (0.12, 0.12, 0.13)))
    for i in range(4):
        v.append(cyl("knob", (d / 2 + 0.03, -0.24 + 0.16 * i, 0.83), 0.022, 0.03, (0.85, 0.85, 0.85), rpy=(0, math.pi / 2, 0)))
    v.append(box("metal_drawer", (d / 2 + 0.01, 0, 0.06), (0.02, w - 0.04, 0.1), (0.7, 0.71, 0.73)))
    write_model("stove", link(v), "A steel stove: black glass cooktop with four burners, oven below.")


def couch():
    L, D = 2.1, 0.9
    fab = (0.14, 0.42, 0.48)
    v = [box("fabric_base", (0, 0, 0.25), (D, L, 0.3), fab)]
    v.append(box("fabric_back", (-D / 2 + 0.1, 0, 0.55), (0.2, L, 0.6), fab))
    for s in (-1, 1):
        v.append(box("fabric_arm", (0.02, s * (L / 2 - 0.1), 0.45), (D - 0.04, 0.2, 0.3), fab))
    for i in range(3):  # seat cushions and back cushions
        y = -L / 2 + 0.2 + (L - 0.4) * (i + 0.5) / 3
        v.append(box("fabric_cushion", (0.06, y, 0.46), (D - 0.26, (L - 0.4) / 3 - 0.02, 0.13), (0.18, 0.5, 0.56)))
        v.append(box("fabric_back_cushion", (-D / 2 + 0.27, y, 0.7), (0.14, (L - 0.4) / 3 - 0.03, 0.4), (0.18, 0.5, 0.56),
                     rpy=(0, -0.12, 0)))
    v.append(box("fabric_pillow", (-0.12, L / 2 - 0.38, 0.66), (0.12, 0.36, 0.36), (0.92, 0.75, 0.2), rpy=(0.3, -0.2, 0)))
    for x in (-D / 2 + 0.06, D / 2 - 0.06):
        for y in (-L / 2 + 0.06, L / 2 - 0.06):
            v.append(cyl("wood_leg", (x, y, 0.05), 0.025, 0.1, (0.3, 0.2, 0.12)))
    write_model("couch", link(v), "A three-seat teal fabric couch with cushions and a yellow pillow.")


def armchair():
    W, D = 0.85, 0.85
    fab = (0.82, 0.6, 0.14)
    v = [box("fabric_base", (0, 0, 0.27), (D, W, 0.3), fab)]
    v.append(box("fabric_back", (-D / 2 + 0.1, 0, 0.62), (0.2, W, 0.7), fab, rpy=(0, -0.08, 0)))
    for s in (-1, 1):
        v.append(box("fabric_arm", (0.02, s * (W / 2 - 0.08), 0.5), (D - 0.04, 0.16, 0.26), fab))
    v.append(box("fabric_cushion", (0.07, 0, 0.47), (D - 0.25, W - 0.32, 0.12), (0.88, 0.68, 0.2)))
    for x in (-D / 2 + 0.07, D / 2 - 0.07):
        for y in (-W / 2 + 0.07, W / 2 - 0.07):
            v.append(cyl("wood_leg", (x, y, 0.06), 0.022, 0.12, (0.3, 0.2, 0.12)))
    write_model("armchair", link(v), "A mustard-yellow fabric armchair.")


WALNUT = (0.42, 0.26, 0.15)


def tv_stand():
    L, D, H = 1.6, 0.42, 0.5
    v = [box("wood_top", (0, 0, H - 0.02), (D, L, 0.04), WALNUT, script="Gazebo/Wood")]
    v.append(box("wood_bottom", (0, 0, 0.1), (D, L, 0.03), WALNUT))
    for y in (-L / 2 + 0.02, -0.27, 0.27, L / 2 - 0.02):
        v.append(box("wood_side", (0, y, (H + 0.08) / 2), (D, 0.04, H - 0.1), WALNUT))
    v.append(box("wood_back", (-D / 2 + 0.01, 0, (H + 0.08) / 2), (0.02, L, H - 0.1), (0.3, 0.18, 0.1)))
    for y in (-0.53, 0.53):  # two drawers with knobs, open shelf in the middle with a console
        v.append(box("wood_drawer", (D / 2 - 0.01, y, 0.3), (0.02, 0.48, 0.3), (0.5, 0.32, 0.19)))
        v.append(sph("metal_knob", (D / 2 + 0.01, y, 0.33), 0.018, HANDLE))
    v.append(box("console", (0.02, 0, 0.15), (0.25, 0.35, 0.06), (0.92, 0.92, 0.93)))
    for x in (-D / 2 + 0.04, D / 2 - 0.04):
        for y in (-L / 2 + 0.04, L / 2 - 0.04):
            v.append(cyl("metal_foot", (x, y, 0.04), 0.02, 0.08, (0.15, 0.15, 0.15)))
    write_model("tv_stand", link(v), "A low walnut TV stand with two drawers.")


def tv():
    W, H = 1.25, 0.72
    v = [box("tv_frame", (0, 0, 0.12 + H / 2), (0.05, W, H), (0.04, 0.04, 0.045))]
    # screen: a lit picture (sky, hills) so the TV is recognisably on
    v.append(box("glass_screen_sky", (0.026, 0, 0.12 + H / 2 + 0.1), (0.002, W - 0.05, H - 0.25), (0.35, 0.55, 0.85)))
    v.append(box("glass_screen_hills", (0.026, 0, 0.12 + 0.14), (0.002, W - 0.05, 0.2), (0.2, 0.5, 0.22)))
    v.append(sph("screen_sun", (0.02, 0.3, 0.12 + H - 0.17), 0.06, (0.98, 0.9, 0.4)))
    v.append(box("metal_neck", (-0.02, 0, 0.08), (0.04, 0.08, 0.12), (0.1, 0.1, 0.1)))
    v.append(box("metal_foot", (0, 0, 0.01), (0.22, 0.5, 0.02), (0.1, 0.1, 0.1)))
    write_model("tv", link(v), "A flat-screen TV on a foot, showing a landscape.")


def bookshelf():
    W, D, H = 1.0, 0.34, 1.9
    wood = (0.58, 0.38, 0.2)
    v = [box("wood_back", (-D / 2 + 0.01, 0, H / 2), (0.02, W, H), (0.48, 0.3, 0.16), script="Gazebo/Wood")]
    for s in (-1, 1):
        v.append(box("wood_side", (0, s * (W / 2 - 0.015), H / 2), (D, 0.03, H), wood, script="Gazebo/Wood"))
    shelves = [0.05, 0.42, 0.8, 1.18, 1.55, H - 0.015]
    for z in shelves:
        v.append(box("wood_shelf", (0, 0, z), (D, W - 0.03, 0.03), wood, script="Gazebo/Wood"))
    colours = [(0.7, 0.1, 0.1), (0.1, 0.25, 0.6), (0.1, 0.45, 0.2), (0.9, 0.75, 0.2), (0.92, 0.9, 0.85),
               (0.35, 0.15, 0.4), (0.1, 0.1, 0.1), (0.85, 0.4, 0.1), (0.2, 0.55, 0.6)]
    for k, z in enumerate(shelves[:-1]):
        y = -W / 2 + 0.04
        while True:
            t = rnd.uniform(0.025, 0.05)
            hb = rnd.uniform(0.2, 0.3)
            if y + t > W / 2 - 0.04 - (0.12 if k % 2 else 0):
                break
            dz = rnd.uniform(0.2, 0.27)
            v.append(box("book", (0.01, y + t / 2, z + 0.015 + hb / 2), (dz, t, hb), rnd.choice(colours)))
            y += t + 0.003
            if k == 2 and y > -0.1 and y < 0:  # a gap and a leaning book
                v.append(box("book", (0.01, y + 0.06, z + 0.13), (0.22, 0.03, 0.24), (0.1, 0.25, 0.6), rpy=(0.35, 0, 0)))
                y += 0.16
        if k % 2:  # a small stack lying flat
            for j in range(3):
                v.append(box("book", (0.0, W / 2 - 0.1, z + 0.03 + 0.035 * j), (0.2, 0.15, 0.03), rnd.choice(colours)))
    write_model("bookshelf", link(v), "A wooden bookshelf with five shelves of books.")


def dining_table():
    L, W, H = 1.6, 0.9, 0.75
    wood = (0.45, 0.27, 0.14)
    v = [box("wood_top", (0, 0, H - 0.02), (L, W, 0.04), wood, script="Gazebo/Wood")]
    v.append(box("wood_apron", (0, 0, H - 0.09), (L - 0.12, W - 0.12, 0.1), (0.4, 0.24, 0.12)))
    for x in (-L / 2 + 0.06, L / 2 - 0.06):
        for y in (-W / 2 + 0.06, W / 2 - 0.06):
            v.append(box("wood_leg", (x, y, (H - 0.04) / 2), (0.06, 0.06, H - 0.04), (0.4, 0.24, 0.12)))
    # a runner, a bowl of fruit and two plates
    v.append(box("fabric_runner", (0, 0, H + 0.002), (L - 0.3, 0.3, 0.004), (0.85, 0.82, 0.72)))
    v.append(cyl("bowl", (0, 0, H + 0.04), 0.13, 0.07, (0.9, 0.9, 0.88)))
    for dx, dy, c in ((0.04, 0.03, (0.9, 0.2, 0.1)), (-0.05, 0.02, (0.95, 0.75, 0.1)), (0.0, -0.05, (0.3, 0.65, 0.15))):
        v.append(sph("fruit", (dx, dy, H + 0.1), 0.045, c))
    for x in (-0.45, 0.45):
        for y in (-0.28, 0.28):
            v.append(cyl("plate", (x, y, H + 0.006), 0.12, 0.01, (0.96, 0.96, 0.97)))
    write_model("dining_table", link(v), "A dark wooden dining table set with plates and a fruit bowl.")


def dining_chair():
    S, H = 0.46, 0.46
    wood = (0.36, 0.2, 0.11)
    v = [box("wood_seat", (0, 0, H - 0.02), (S, S, 0.04), wood, script="Gazebo/Wood")]
    v.append(box("fabric_seat_pad", (0.01, 0, H + 0.015), (S - 0.05, S - 0.05, 0.03), (0.6, 0.1, 0.13)))
    for x in (-S / 2 + 0.03, S / 2 - 0.03):
        for y in (-S / 2 + 0.03, S / 2 - 0.03):
            v.append(box("wood_leg", (x, y, (H - 0.04) / 2), (0.04, 0.04, H - 0.04), wood))
    for y in (-S / 2 + 0.03, S / 2 - 0.03):
        v.append(box("wood_post", (-S / 2 + 0.03, y, H + 0.23), (0.04, 0.04, 0.46), wood))
    for z in (H + 0.2, H + 0.4):
        v.append(box("wood_rail", (-S / 2 + 0.03, 0, z), (0.03, S - 0.04, 0.07), wood))
    write_model("dining_chair", link(v), "A wooden dining chair with a red seat pad.")


def bed():
    L, W = 2.05, 1.6
    v = [box("wood_frame", (0, 0, 0.2), (L, W, 0.2), (0.55, 0.4, 0.26), script="Gazebo/Wood")]
    v.append(box("wood_headboard", (-L / 2 + 0.04, 0, 0.6), (0.08, W + 0.04, 1.0), (0.5, 0.36, 0.22), script="Gazebo/Wood"))
    v.append(box("mattress", (0.02, 0, 0.4), (L - 0.1, W - 0.06, 0.2), (0.95, 0.95, 0.93), script="fabric"))
    v.append(box("fabric_duvet", (0.25, 0, 0.52), (L - 0.55, W + 0.02, 0.06), (0.32, 0.48, 0.76)))
    v.append(box("fabric_duvet_side", (0.25, 0, 0.36), (L - 0.55, W + 0.06, 0.3), (0.32, 0.48, 0.76)))
    v.append(box("fabric_fold", (-0.05, 0, 0.56), (0.2, W + 0.02, 0.05), (0.9, 0.9, 0.95)))
    for y in (-0.38, 0.38):
        v.append(box("fabric_pillow", (-L / 2 + 0.3, y, 0.57), (0.38, 0.6, 0.14), (0.97, 0.97, 0.98), rpy=(0, -0.2, 0)))
    for x in (-L / 2 + 0.05, L / 2 - 0.05):
        for y in (-W / 2 + 0.05, W / 2 - 0.05):
            v.append(box("wood_leg", (x, y, 0.05), (0.07, 0.07, 0.1), (0.4, 0.28, 0.17)))
    write_model("bed", link(v), "A double bed with a blue duvet, white pillows and a wooden headboard.")


def wardrobe():
    W, D, H = 1.2, 0.6, 2.0
    wood = (0.78, 0.63, 0.45)
    v = [box("wood_body", (0, 0, H / 2 + 0.05), (D, W, H - 0.1), wood, script="Gazebo/Wood")]
    v.append(box("plinth", (-0.02, 0, 0.05), (D - 0.06, W - 0.04, 0.1), (0.2, 0.15, 0.1)))
    v.append(box("wood_crown", (0.01, 0, H + 0.02), (D + 0.04, W + 0.04, 0.04), (0.7, 0.55, 0.38)))
    for s in (-1, 1):
        v.append(box("wood_door", (D / 2 + 0.01, s * W / 4, H / 2 + 0.12), (0.02, W / 2 - 0.02, H - 0.45), (0.82, 0.68, 0.5),
                     script="Gazebo/Wood"))
        v.append(box("metal_handle", (D / 2 + 0.04, s * 0.05, H / 2 + 0.25), (0.02, 0.02, 0.3), HANDLE))
        v.append(box("wood_drawer", (D / 2 + 0.01, s * W / 4, 0.22), (0.02, W / 2 - 0.02, 0.2), (0.82, 0.68, 0.5)))
        v.append(box("metal_pull", (D / 2 + 0.03, s * W / 4, 0.25), (0.02, 0.16, 0.02), HANDLE))
    v.append(box("glass_mirror", (D / 2 + 0.021, W / 4, H / 2 + 0.2), (0.002, 0.34, 1.0), (0.75, 0.82, 0.88)))
    write_model("wardrobe", link(v), "A tall light-wood wardrobe with two doors, drawers and a mirror.")


def window():
    W, H = 1.2, 1.2  # the opening; the model sits in the wall, origin at the opening's centre
    white = (0.96, 0.96, 0.96)
    v = [box("glass_pane", (0, 0, 0), (0.01, W - 0.08, H - 0.08), (0.62, 0.8, 0.95))]
    for s in (-1, 1):
        v.append(box("frame_side", (0, s * (W / 2 - 0.03), 0), (0.14, 0.06, H), white))
        v.append(box("frame_head", (0, 0, s * (H / 2 - 0.03)), (0.14, W, 0.06), white))
    v.append(box("frame_mullion", (0, 0, 0), (0.06, 0.04, H - 0.08), white))
    v.append(box("frame_transom", (0, 0, 0.15), (0.06, W - 0.08, 0.04), white))
    v.append(box("sill", (0.1, 0, -H / 2 - 0.02), (0.12, W + 0.1, 0.03), white))
    write_model("window", link(v), "A white-framed window with four panes.")


def door():
    W, H = 0.88, 2.05  # origin at the hinge side bottom; the leaf extends along +y
    v = [box("leaf", (0, W / 2, H / 2), (0.04, W, H), (0.93, 0.92, 0.88))]
    for z in (0.45, 1.25):
        for x in (-0.022, 0.022):
            v.append(box("panel", (x, W / 2, z + 0.3), (0.005, W - 0.24, 0.6 if z < 1 else 0.55), (0.86, 0.85, 0.8)))
    for x in (-0.05, 0.05):
        v.append(box("metal_lever", (x, W - 0.08, 1.0), (0.02, 0.12, 0.02), HANDLE))
    v.append(cyl("metal_rose", (0, W - 0.06, 1.0), 0.03, 0.08, HANDLE, rpy=(0, math.pi / 2, 0)))
    write_model("door", link(v), "A white panelled interior door with a lever handle.")


for fn in (refrigerator, kitchen_counter, sink, stove, couch, armchair, tv_stand, tv, bookshelf,
           dining_table, dining_chair, bed, wardrobe, window, door):
    fn()

# ---- the world ---------------------------------------------------------------------------------
HW = 2.6       # wall height
T = 0.14       # wall thickness
ROOM_PAINT = {"living": (0.93, 0.87, 0.74), "kitchen": (0.86, 0.9, 0.8), "dining": (0.95, 0.8, 0.68),
              "hall": (0.86, 0.86, 0.84), "bed": (0.74, 0.82, 0.92), "out": (0.88, 0.84, 0.78)}
walls = []
n_wall = [0]


def wall(x0, y0, x1, y1, side_a, side_b, openings=()):
    """An axis-aligned wall from (x0,y0) to (x1,y1); side_a is the room on the -normal side
    (south or west), side_b the other. openings: (start, end, z0, z1) along the wall."""
    horiz = y0 == y1
    L = abs(x1 - x0) if horiz else abs(y1 - y0)
    s0 = min(x0, x1) if horiz else min(y0, y1)
    pieces = []  # (a, b, z0, z1) in wall coordinates
    cuts = sorted(openings)
    a = 0.0
    for o0, o1, z0, z1 in cuts:
        o0 -= s0
        o1 -= s0
        if o0 > a:
            pieces.append((a, o0, 0, HW))
        if z0 > 0:
            pieces.append((o0, o1, 0, z0))
        if z1 < HW:
            pieces.append((o0, o1, z1, HW))
        a = o1
    if a < L:
        pieces.append((a, L, 0, HW))
    for (pa, pb, z0, z1) in pieces:
        for side, room in ((-1, side_a), (1, side_b)):
            n_wall[0] += 1
            c = s0 + (pa + pb) / 2
            off = side * T / 4
            if horiz:
                pos, size = (c, y0 + off, (z0 + z1) / 2), (pb - pa, T / 2, z1 - z0)
            else:
                pos, size = (x0 + off, c, (z0 + z1) / 2), (T / 2, pb - pa, z1 - z0)
            walls.append(box("plaster_%s_%d" % (room, n_wall[0]), pos, size, ROOM_PAINT[room]))


WIN = (0.9, 2.1)
DOOR_Z = (0, 2.12)
# exterior
wall(0, 0, 6.5, 0, "out", "living", [(1.8, 3.0, *WIN), (4.3, 5.5, *WIN)])
wall(6.5, 0, 10, 0, "out", "hall", [(8.0, 8.95, *DOOR_Z)])
wall(0, 8, 3.5, 8, "kitchen", "out", [(1.5, 2.7, *WIN)])
wall(3.5, 8, 6.5, 8, "dining", "out", [(4.4, 5.6, *WIN)])
wall(6.5, 8, 10, 8, "bed", "out", [(7.4, 8.6, *WIN)])
wall(0, 0, 0, 4.5, "out", "living", [])
wall(0, 4.5, 0, 8, "out", "kitchen", [])
wall(10, 0, 10, 3, "hall", "out", [])
wall(10, 3, 10, 8, "bed", "out", [(3.6, 4.8, *WIN)])
# interior
wall(0, 4.5, 3.5, 4.5, "living", "kitchen", [(2.5, 3.4, *DOOR_Z)])
wall(3.5, 4.5, 6.5, 4.5, "living", "dining", [(4.0, 6.2, 0, 2.3)])
wall(3.5, 4.5, 3.5, 8, "kitchen", "dining", [(5.3, 7.0, 0, 2.3)])
wall(6.5, 0, 6.5, 3, "living", "hall", [(1.0, 1.95, *DOOR_Z)])
wall(6.5, 3, 6.5, 4.5, "living", "bed", [])
wall(6.5, 4.5, 6.5, 8, "dining", "bed", [])
wall(6.5, 3, 10, 3, "hall", "bed", [(8.0, 8.95, *DOOR_Z)])

floors = [
    box("floor_living", (3.25, 2.25, -0.01), (6.5, 4.5, 0.02), (0.62, 0.44, 0.27), script="Gazebo/WoodFloor"),
    box("floor_kitchen", (1.75, 6.25, -0.01), (3.5, 3.5, 0.02), (0.85, 0.85, 0.82), script="Gazebo/Tiles"),
    box("floor_dining", (5.0, 6.25, -0.01), (3.0, 3.5, 0.02), (0.55, 0.38, 0.22), script="Gazebo/WoodFloor"),
    box("floor_hall", (8.25, 1.5, -0.01), (3.5, 3.0, 0.02), (0.72, 0.42, 0.3), script="Gazebo/Tiles"),
    box("floor_bedroom", (8.25, 5.5, -0.01), (3.5, 5.0, 0.02), (0.45, 0.5, 0.58), script="Gazebo/Carpet"),
]
ceiling = [box("plaster_ceiling", (5, 4, HW + 0.01), (10, 8, 0.02), (0.96, 0.96, 0.95))]


def inc(model, name, x, y, yaw, z=0.0):
    return ("  <include>\n    <uri>model://%s</uri>\n    <name>%s</name>\n    <pose>%s 0 0 %.4f</pose>\n  </include>\n"
            % (model, name, f((x, y, z)), yaw))


P = math.pi
objs = []
# kitchen: fridge in the NW corner facing south, counters along the north and west walls
objs.append(inc("refrigerator", "refrigerator", 0.45, 7.55, -P / 2))
objs.append(inc("kitchen_counter", "kitchen_counter_1", 1.0, 7.62, -P / 2))
objs.append(inc("sink", "sink", 2.1, 7.62, -P / 2))
objs.append(inc("stove", "stove", 2.97, 7.61, -P / 2))
objs.append(inc("kitchen_counter", "kitchen_counter_2", 0.38, 5.6, 0))
# living room: TV on its stand against the north wall, couch facing it, coffee table, armchair
objs.append(inc("tv_stand", "tv_stand", 1.5, 4.2, -P / 2))
objs.append(inc("tv", "tv", 1.5, 4.27, -P / 2, z=0.5))
objs.append(inc("couch", "couch", 1.5, 1.05, P / 2))
objs.append(inc("armchair", "armchair", 3.25, 2.55, P))
objs.append(inc("bookshelf", "bookshelf", 0.25, 3.3, 0))
# dining: table with four chairs facing it
objs.append(inc("dining_table", "dining_table", 5.0, 6.3, 0))
for i, (x, y, yaw) in enumerate(((4.6, 5.58, P / 2), (5.4, 5.58, P / 2), (4.6, 7.02, -P / 2), (5.4, 7.02, -P / 2))):
    objs.append(inc("dining_chair", "dining_chair_%d" % (i + 1), x, y, yaw))
# bedroom: bed with its head to the east wall, wardrobe on the west wall
objs.append(inc("bed", "bed", 8.95, 6.0, P))
objs.append(inc("wardrobe", "wardrobe", 6.87, 6.4, 0))
# doors: the front door (closed) and the bedroom door (open against the wall)
objs.append(inc("door", "front_door", 8.02, 0.0, -P / 2))
objs.append(inc("door", "bedroom_door", 8.04, 3.1, -P / 2 + 1.4))
# windows sit in the wall openings (origin at the opening centre, facing into the room)
wins = [(2.4, 0, P / 2), (4.9, 0, P / 2), (2.1, 8, -P / 2), (5.0, 8, -P / 2), (8.0, 8, -P / 2), (10, 4.2, P)]
for i, (x, y, yaw) in enumerate(wins):
    objs.append(inc("window", "window_%d" % (i + 1), x, y, yaw, z=1.5))

inline = """
  <model name="coffee_table">
    <static>true</static>
    <pose>1.5 2.45 0 0 0 0</pose>
    <link name="link">
      %s
    </link>
  </model>
  <model name="rug">
    <static>true</static>
    <pose>1.5 2.4 0 0 0 0</pose>
    <link name="link">%s</link>
  </model>
  <model name="nightstand">
    <static>true</static>
    <pose>9.65 7.3 0 0 0 3.1416</pose>
    <link name="body">%s</link>
    <model name="lamp">
      <pose>0 0 0.55 0 0 0</pose>
      <link name="lamp_link">%s</link>
    </model>
  </model>
  <model name="potted_plant">
    <static>true</static>
    <pose>6.05 0.45 0 0 0 0</pose>
    <link name="link">%s</link>
  </model>
""" % (
    "\n      ".join([box("wood_top", (0, 0, 0.42), (1.0, 0.55, 0.04), (0.72, 0.52, 0.3), script="Gazebo/Wood"),
                    box("wood_shelf", (0, 0, 0.12), (0.9, 0.45, 0.02), (0.72, 0.52, 0.3))] +
                   [box("wood_leg", (x, y, 0.2), (0.05, 0.05, 0.4), (0.5, 0.34, 0.2))
                    for x in (-0.45, 0.45) for y in (-0.24, 0.24)] +
                   [box("book", (0.2, 0.1, 0.455), (0.26, 0.2, 0.03), (0.1, 0.3, 0.6)),
                    cyl("mug", (-0.25, -0.1, 0.49), 0.04, 0.1, (0.9, 0.3, 0.2))]),
    box("rug_carpet", (0, 0, 0.004), (2.4, 1.7, 0.008), (0.62, 0.2, 0.18)),
    "".join([box("wood_body", (0, 0, 0.27), (0.42, 0.45, 0.5), (0.55, 0.4, 0.26), script="Gazebo/Wood"),
             box("wood_drawer", (0.215, 0, 0.38), (0.01, 0.38, 0.16), (0.6, 0.45, 0.3)),
             sph("metal_knob", (0.23, 0, 0.38), 0.015, HANDLE)]),
    "".join([cyl("lamp_base", (0, 0, 0.01), 0.07, 0.02, (0.2, 0.2, 0.2)),
             cyl("lamp_stem", (0, 0, 0.17), 0.012, 0.3, (0.2, 0.2, 0.2)),
             cyl("fabric_lamp_shade", (0, 0, 0.36), 0.13, 0.18, (0.98, 0.92, 0.75))]),
    "".join([cyl("pot", (0, 0, 0.18), 0.17, 0.36, (0.72, 0.35, 0.2)),
             cyl("soil", (0, 0, 0.355), 0.155, 0.01, (0.2, 0.13, 0.08))] +
            [sph("leaves", (0.12 * math.cos(a), 0.12 * math.sin(a), 0.6 + 0.15 * (k % 2)), 0.16, (0.15, 0.45 + 0.08 * (k % 3), 0.15))
             for k, a in enumerate([i * 2 * math.pi / 5 for i in range(5)])] +
            [sph("leaves", (0, 0, 0.85), 0.18, (0.18, 0.52, 0.17)),
             cyl("stem", (0, 0, 0.45), 0.02, 0.2, (0.3, 0.22, 0.1))]),
)

def painting(name, x, y, z, yaw, w, h, palette):
    """A framed picture hanging on a wall (origin at its centre, facing +x)."""
    v = [box("wood_frame", (0, 0, 0), (0.03, w, h), (0.25, 0.17, 0.1))]
    v.append(box("canvas", (0.016, 0, 0), (0.002, w - 0.08, h - 0.08), palette[0]))
    r = random.Random(name)
    for k in range(7):
        cw, ch = r.uniform(0.1, 0.45) * (w - 0.1), r.uniform(0.1, 0.45) * (h - 0.1)
        cy, cz = r.uniform(-(w - 0.1 - cw) / 2, (w - 0.1 - cw) / 2), r.uniform(-(h - 0.1 - ch) / 2, (h - 0.1 - ch) / 2)
        v.append(box("paint", (0.018 + 0.001 * k, cy, cz), (0.002, cw, ch), palette[1 + k % (len(palette) - 1)]))
    return ('  <model name="%s">\n    <static>true</static>\n    <pose>%s 0 0 %.4f</pose>\n    <link name="link">%s</link>\n  </model>\n'
            % (name, f((x, y, z)), yaw, "".join(v)))


inline += painting("painting_1", 0.08, 1.0, 1.5, 0, 0.9, 0.6, [(0.95, 0.93, 0.85), (0.85, 0.3, 0.2), (0.2, 0.35, 0.7), (0.95, 0.75, 0.2)])
inline += painting("painting_2", 6.42, 6.3, 1.5, P, 1.0, 0.7, [(0.2, 0.3, 0.25), (0.9, 0.85, 0.7), (0.6, 0.75, 0.3), (0.8, 0.4, 0.5)])
inline += painting("painting_3", 9.92, 1.5, 1.5, P, 0.7, 0.9, [(0.9, 0.88, 0.8), (0.15, 0.2, 0.4), (0.3, 0.6, 0.7), (0.9, 0.5, 0.15)])
inline += painting("painting_4", 9.3, 7.92, 1.55, -P / 2, 0.8, 0.5, [(0.85, 0.9, 0.95), (0.35, 0.5, 0.8), (0.95, 0.95, 0.97), (0.3, 0.6, 0.35)])
inline += painting("painting_5", 6.42, 3.7, 1.55, P, 0.6, 0.8, [(0.3, 0.15, 0.12), (0.95, 0.8, 0.4), (0.8, 0.2, 0.15), (0.95, 0.95, 0.9)])
inline += """
  <model name="shoe_cabinet">
    <static>true</static>
    <pose>9.75 1.6 0 0 0 3.1416</pose>
    <link name="link">%s</link>
  </model>
  <model name="coat_rack">
    <static>true</static>
    <pose>6.9 0.35 0 0 0 0</pose>
    <link name="link">%s</link>
  </model>
""" % ("".join([box("wood_body", (0, 0, 0.45), (0.35, 1.0, 0.9), (0.3, 0.32, 0.36)),
               box("wood_top", (0.01, 0, 0.91), (0.37, 1.02, 0.03), (0.55, 0.38, 0.22), script="Gazebo/Wood")] +
              [box("door", (0.18, y, 0.45), (0.01, 0.47, 0.8), (0.35, 0.37, 0.42)) for y in (-0.25, 0.25)] +
              [box("metal_handle", (0.2, y, 0.7), (0.02, 0.12, 0.02), HANDLE) for y in (-0.08, 0.08)] +
              [cyl("bowl", (0, 0.3, 0.96), 0.1, 0.06, (0.2, 0.5, 0.6)),
               box("mail", (0.02, -0.2, 0.935), (0.2, 0.3, 0.02), (0.95, 0.95, 0.9))]),
     "".join([cyl("metal_pole", (0, 0, 0.9), 0.02, 1.8, (0.15, 0.15, 0.15)),
              cyl("metal_foot", (0, 0, 0.02), 0.22, 0.04, (0.15, 0.15, 0.15))] +
             [box("metal_hook", (0.08 * math.cos(a), 0.08 * math.sin(a), 1.7), (0.16, 0.02, 0.02), (0.15, 0.15, 0.15),
                  rpy=(0, -0.5, a)) for a in (0, 1.6, 3.2, 4.8)] +
             [box("fabric_coat", (0.12, 0.0, 1.3), (0.12, 0.45, 0.75), (0.55, 0.12, 0.1), rpy=(0, 0.05, 0)),
              box("fabric_scarf", (-0.1, 0.05, 1.45), (0.06, 0.2, 0.5), (0.95, 0.8, 0.2))]))

# inline models get their collision shapes too
inline = re.sub(r'(<link name="[^"]*">)(.*?)(</link>)',
                lambda m: m.group(1) + m.group(2) + "".join(collisions(re.findall(r"<visual .*?</visual>", m.group(2), re.S))) + m.group(3),
                inline, flags=re.S)

lights = ""
for name, (x, y) in (("living", (1.8, 2.2)), ("living_east", (5.0, 2.2)), ("kitchen", (1.75, 6.2)),
                     ("dining", (5.0, 6.2)), ("hall", (8.25, 1.5)), ("bedroom", (8.3, 5.5))):
    lights += """  <light name="light_%s" type="point">
    <pose>%s 2.35 0 0 0</pose>
    <diffuse>0.75 0.72 0.65 1</diffuse>
    <specular>0.1 0.1 0.1 1</specular>
    <attenuation><range>12</range><constant>0.4</constant><linear>0.12</linear><quadratic>0.06</quadratic></attenuation>
    <cast_shadows>false</cast_shadows>
  </light>
""" % (name, f((x, y)))

world = """<?xml version="1.0"?>
<!-- The semsplat house: a one-storey home of about 10 m x 8 m (kitchen, dining area, living room,
     hall and bedroom) for tests, the demo and evaluation. Generated by house_models/make_house.py;
     models are included from house_models/ (model://), a few are inline. -->
<sdf version="1.6">
<world name="semsplat_house">
  <scene>
    <ambient>0.38 0.38 0.38 1</ambient>
    <background>0.7 0.8 0.95 1</background>
    <shadows>false</shadows>
  </scene>
  <light name="sun" type="directional">
    <pose>0 0 10 0 0 0</pose>
    <diffuse>0.35 0.35 0.33 1</diffuse>
    <direction>-0.4 0.25 -0.88</direction>
  </light>
%s
  <model name="walls">
    <static>true</static>
    <link name="link">
%s
    </link>
  </model>
  <model name="floor">
    <static>true</static>
    <link name="link">
%s
    </link>
  </model>
  <model name="ceiling">
    <static>true</static>
    <link name="link">
%s
    </link>
  </model>
%s
%s
</world>
</sdf>
""" % (lights, "\n".join(walls + collisions(walls)), "\n".join(floors + collisions(floors)),
       "\n".join(ceiling), "".join(objs), inline)

with open(WORLD, "w") as fh:
    fh.write(world)
print("wrote", WORLD)
