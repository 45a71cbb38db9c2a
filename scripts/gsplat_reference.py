"""Quality anchor: gsplat's simple_trainer recipe (default strategy, 3DGS learning rates, L1 + SSIM)
trained on a semsplat capture, so `semsplat train` can be compared with gsplat on the same data in
the same device call. Run on the GPU machine with gsplat importable (see
shared/bench/anchors/run_device.sh, which builds it):

    python3 scripts/gsplat_reference.py CAPTURE --steps 7000 [--schedule 30000] [--sh-degree 3]

CAPTURE holds sparse/0/{cameras,images,points3D}.bin and images/. Every 8th image (sorted by name)
is held out, as simple_trainer and semsplat do. The strategy is gsplat's DefaultStrategy with its
defaults (refine every 100 steps from 500 to 15000, opacity reset every 3000), as simple_trainer
runs it whatever --max_steps is; --schedule N decays the means learning rate over N steps
(simple_trainer's max_steps), so --schedule 30000 --steps 7000 gives its 7k checkpoint.
Prints one JSON line with held-out PSNR, SSIM, the Gaussian count and seconds."""
import argparse, json, math, os, struct, sys, time

import numpy as np
import torch
import torch.nn.functional as F
from gsplat import rasterization
from gsplat.strategy import DefaultStrategy


def read_cameras(path):
    cams = {}
    with open(path, "rb") as f:
        (n,) = struct.unpack("<Q", f.read(8))
        for _ in range(n):
            cid, model, w, h = struct.unpack("<iiQQ", f.read(24))
            npar = {0: 3, 1: 4}.get(model)
            if npar is None:
                sys.exit("camera %d: model %d is not PINHOLE/SIMPLE_PINHOLE" % (cid, model))
            p = struct.unpack("<%dd" % npar, f.read(8 * npar))
            fx, fy, cx, cy = (p[0], p[0], p[1], p[2]) if model == 0 else p
            cams[cid] = (w, h, fx, fy, cx, cy)
    return cams


def read_images(path):
    imgs = []
    with open(path, "rb") as f:
        (n,) = struct.unpack("<Q", f.read(8))
        for _ in range(n):
            iid, qw, qx, qy, qz, tx, ty, tz, cid = struct.unpack("<idddddddi", f.read(64))
            name = b""
            while (c := f.read(1)) != b"\0":
                name += c
            (np2d,) = struct.unpack("<Q", f.read(8))
            f.read(24 * np2d)
            imgs.append((name.decode(), np.array([qw, qx, qy, qz]), np.array([tx, ty, tz]), cid))
    return sorted(imgs)


def read_points(path):
    xyz, rgb = [], []
    with open(path, "rb") as f:
        (n,) = struct.unpack("<Q", f.read(8))
        for _ in range(n):
            _, x, y, z, r, g, b, _ = struct.unpack("<QdddBBBd", f.read(43))
            (tl,) = struct.unpack("<Q", f.read(8))
            f.read(8 * tl)
            xyz.append((x, y, z))
            rgb.append((r, g, b))
    return np.array(xyz, np.float32), np.array(rgb, np.float32) / 255.0


def quat_to_rot(q):
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def load_image(path):
    try:
        from PIL import Image
        return np.asarray(Image.open(path).convert("RGB"))
    except ImportError:
        from torchvision.io import read_image
        return read_image(path).permute(1, 2, 0).numpy()[..., :3]


def ssim(a, b):
    """SSIM of [1,3,H,W] images, 11x11 Gaussian window (sigma 1.5), valid padding (fused_ssim's)."""
    g = torch.exp(-((torch.arange(11, device=a.device) - 5.0) ** 2) / (2 * 1.5 ** 2))
    g = (g / g.sum())
    w = (g[:, None] * g[None, :]).expand(3, 1, 11, 11).contiguous()
    f = lambda x: F.conv2d(x, w, groups=3)
    mu_a, mu_b = f(a), f(b)
    saa, sbb, sab = f(a * a) - mu_a ** 2, f(b * b) - mu_b ** 2, f(a * b) - mu_a * mu_b
    c1, c2 = 0.01 ** 2, 0.03 ** 2
    s = ((2 * mu_a * mu_b + c1) * (2 * sab + c2)) / ((mu_a ** 2 + mu_b ** 2 + c1) * (saa + sbb + c2))
    return s.mean()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("capture")
    ap.add_argument("--steps", type=int, default=7000)
    ap.add_argument("--schedule", type=int, default=0, help="schedule length (default: --steps)")
    ap.add_argument("--sh-degree", type=int, default=3)
    ap.add_argument("--seed", type=int, default=42)
    a = ap.parse_args()
    sched = a.schedule or a.steps
    torch.manual_seed(a.seed)
    dev = "cuda"
    sp = os.path.join(a.capture, "sparse", "0")
    for f in ("cameras.bin", "images.bin", "points3D.bin"):
        if not os.path.isfile(os.path.join(sp, f)):
            sys.exit("error: %s is missing (need a binary COLMAP model in CAPTURE/sparse/0)" % os.path.join(sp, f))
    cams, views = read_cameras(os.path.join(sp, "cameras.bin")), read_images(os.path.join(sp, "images.bin"))
    xyz, rgb = read_points(os.path.join(sp, "points3D.bin"))
    data = []
    for name, q, t, cid in views:
        w, h, fx, fy, cx, cy = cams[cid]
        V = np.eye(4)
        V[:3, :3], V[:3, 3] = quat_to_rot(q), t
        K = np.array([[fx, 0, cx], [0, fy, cy], [0, 0, 1]])
        path = os.path.join(a.capture, "images", name)
        if not os.path.isfile(path):
            sys.exit("error: image %s (listed in images.bin) is missing" % path)
        img = torch.from_numpy(load_image(path).copy()).float() / 255
        if img.shape[:2] != (h, w):
            sys.exit("error: %s is %dx%d, its camera says %dx%d" % (path, img.shape[1], img.shape[0], w, h))
        data.append((torch.tensor(V, dtype=torch.float32, device=dev), torch.tensor(K, dtype=torch.float32, device=dev),
                     img.to(dev), w, h))
    test = [d for i, d in enumerate(data) if i % 8 == 0]
    train = [d for i, d in enumerate(data) if i % 8 != 0]
    centers = np.stack([-quat_to_rot(q).T @ t for _, q, t, _ in views])
    scene_scale = float(np.linalg.norm(centers - centers.mean(0), axis=1).max()) * 1.1

    pts = torch.from_numpy(xyz).to(dev)
    d2 = torch.cat([torch.cdist(pts[i:i + 4096], pts).topk(4, largest=False).values[:, 1:] ** 2
                    for i in range(0, len(pts), 4096)])
    dist = d2.mean(-1).sqrt()
    n = len(pts)
    K_sh = (a.sh_degree + 1) ** 2
    C0 = 0.28209479177387814
    shs = torch.zeros(n, K_sh, 3, device=dev)
    shs[:, 0] = (torch.from_numpy(rgb).to(dev) - 0.5) / C0
    params = torch.nn.ParameterDict({
        "means": pts, "scales": torch.log(dist)[:, None].repeat(1, 3),
        "quats": torch.rand(n, 4, device=dev), "opacities": torch.logit(torch.full((n,), 0.1, device=dev)),
        "sh0": shs[:, :1].clone(), "shN": shs[:, 1:].clone()}).to(dev)
    lrs = {"means": 1.6e-4 * scene_scale, "scales": 5e-3, "quats": 1e-3, "opacities": 5e-2,
           "sh0": 2.5e-3, "shN": 2.5e-3 / 20}
    opts = {k: torch.optim.Adam([{"params": params[k], "lr": lr, "name": k}], eps=1e-15)
            for k, lr in lrs.items()}
    sched_means = torch.optim.lr_scheduler.ExponentialLR(opts["means"], gamma=0.01 ** (1.0 / sched))
    strategy = DefaultStrategy(verbose=False)
    strategy.check_sanity(params, opts)
    state = strategy.initialize_state(scene_scale=scene_scale)

    def render(d, deg):
        V, K, img, w, h = d
        colors = torch.cat([params["sh0"], params["shN"]], 1)
        out, alpha, info = rasterization(params["means"], params["quats"], torch.exp(params["scales"]),
                                         torch.sigmoid(params["opacities"]), colors, V[None], K[None], w, h,
                                         sh_degree=deg, packed=False)
        return out[0], info

    t0 = time.time()
    order = torch.randperm(len(train)).tolist()
    for step in range(a.steps):
        if not order:
            order = torch.randperm(len(train)).tolist()
        d = train[order.pop()]
        deg = min(step // 1000, a.sh_degree)
        out, info = render(d, deg)
        strategy.step_pre_backward(params, opts, state, step, info)
        gt = d[2]
        l1 = (out - gt).abs().mean()
        loss = 0.8 * l1 + 0.2 * (1 - ssim(out.permute(2, 0, 1)[None], gt.permute(2, 0, 1)[None]))
        loss.backward()
        for o in opts.values():
            o.step()
            o.zero_grad(set_to_none=True)
        sched_means.step()
        strategy.step_post_backward(params, opts, state, step, info, packed=False)
        if step % 1000 == 0:
            print("step %d loss %.4f n %d" % (step, loss.item(), len(params["means"])), file=sys.stderr)
    torch.cuda.synchronize()
    secs = time.time() - t0
    with torch.no_grad():
        ps, ss = [], []
        for d in test:
            out, _ = render(d, min((a.steps - 1) // 1000, a.sh_degree))
            out = out.clamp(0, 1)
            mse = ((out - d[2]) ** 2).mean()
            ps.append(-10 * math.log10(mse.item()))
            ss.append(ssim(out.permute(2, 0, 1)[None], d[2].permute(2, 0, 1)[None]).item())
    print(json.dumps({"what": "gsplat_train", "steps": a.steps, "schedule": sched, "sh_degree": a.sh_degree,
                      "psnr": sum(ps) / len(ps), "ssim": sum(ss) / len(ss), "gaussians": len(params["means"]),
                      "seconds": secs, "eval_views": len(test)}))


if __name__ == "__main__":
    main()
