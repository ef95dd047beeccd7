"""paraview.py: read the program's VTU files back with a real reader, meshio.

    paraview.py state DIR E NU MODEL   solution.vtu of a solve folder DIR
                                       against its text files
    paraview.py pvd DIR E NU MODEL     iterates.pvd and iterates/ of an
                                       optimize folder DIR

Every check prints one line, "ok - ..." or "FAIL - ...", as tests/lib.sh
does; the exit status is 1 if any check failed. E [Pa], NU and MODEL
(plane_stress or plane_strain) are the scene's material, for the stress
recomputed here from the displacements alone.
"""
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

try:
    import meshio
except ImportError:
    print("FAIL - paraview.py: python3-meshio is missing (make deps installs it)")
    sys.exit(1)
try:        # VTK's own reader, ParaView's, where python3-vtk9 is installed
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    vtk = None

failures = 0


def check(what, ok):
    global failures
    print(("ok - " if ok else "FAIL - ") + what)
    failures += not ok


def columns(path):
    """The data rows of a text file of the program, as a 2-D array."""
    return np.atleast_2d(np.loadtxt(path, comments="#"))


def point_array(mesh, name):
    """A point array, one row per point (scalars as a vector)."""
    a = mesh.point_data[name]
    return a.reshape(len(a), -1) if a.ndim > 1 else a.reshape(-1, 1)


def cell_array(mesh, name):
    return np.asarray(mesh.cell_data[name][0]).reshape(-1)


def close(a, b, rel):
    """|a - b| <= rel max|b| everywhere (the files print 15 digits)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a.shape == b.shape and np.all(np.abs(a - b) <= rel * max(np.abs(b).max(), 1e-300))


# ---- the stress of a linear triangle, from nothing but the file -----------
def hooke(E, nu, model):
    """D of stress = D (e11, e22, 2 e12), and lambda, for MODEL."""
    mu = E / (2 * (1 + nu))
    lam = E * nu / ((1 + nu) * (1 - 2 * nu)) if model == "plane_strain" \
        else E * nu / (1 - nu * nu)
    return np.array([[lam + 2 * mu, lam, 0], [lam, lam + 2 * mu, 0], [0, 0, mu]]), lam


def stresses(points, tri, u, E, nu, model):
    """sigma11, sigma22, sigma12, sigma33 and von Mises of every triangle."""
    x, y = points[tri, 0], points[tri, 1]            # ntri x 3
    u1, u2 = u[tri, 0], u[tri, 1]
    gx = np.roll(y, -1, axis=1) - np.roll(y, -2, axis=1)   # y_{k+1} - y_{k+2}
    gy = np.roll(x, -2, axis=1) - np.roll(x, -1, axis=1)   # x_{k+2} - x_{k+1}
    area2 = (x[:, 1] - x[:, 0]) * (y[:, 2] - y[:, 0]) - (x[:, 2] - x[:, 0]) * (y[:, 1] - y[:, 0])
    strain = np.stack([(gx * u1).sum(1), (gy * u2).sum(1),
                       (gy * u1 + gx * u2).sum(1)], axis=1) / area2[:, None]
    D, lam = hooke(E, nu, model)
    s = strain @ D.T
    s33 = lam * (strain[:, 0] + strain[:, 1]) if model == "plane_strain" else 0 * s[:, 0]
    vm = np.sqrt(0.5 * ((s[:, 0] - s[:, 1]) ** 2 + (s[:, 1] - s33) ** 2 + (s33 - s[:, 0]) ** 2)
                 + 3 * s[:, 2] ** 2)
    return np.column_stack([s, s33, vm])


# ---- solution.vtu against nodes.dat, contact.dat and summary.dat ----------
def check_format(path, label):
    raw = open(path, "rb").read()
    head = raw[:raw.find(b"<AppendedData")]
    check(f"{label}: binary: raw appended data, a UInt64 header per array, no ASCII array",
          b'header_type="UInt64"' in head and b'<AppendedData encoding="raw">' in raw
          and b'format="ascii"' not in head and head.count(b'format="appended"') >= 12)


def check_vtk(path, mesh, label):
    """VTK's XML reader finds the triangles and every array meshio found,
    with the same values; meshio is the lenient one (it took connectivity
    as three components, which VTK refuses). Not a check without VTK."""
    if vtk is None:
        print(f"# {label}: VTK's reader not checked: python3-vtk9 is not installed")
        return
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    same = g.GetNumberOfPoints() == len(mesh.points) and g.GetNumberOfCells() == len(mesh.cells[0].data)
    same = same and all(g.GetCellType(c) == 5 for c in range(g.GetNumberOfCells()))
    ours = [(g.GetPointData(), name, v) for name, v in mesh.point_data.items()] + \
           [(g.GetCellData(), name, v[0]) for name, v in mesh.cell_data.items()]
    for data, name, values in ours:
        a = data.GetArray(name)
        same = same and a is not None and np.array_equal(
            vtk_to_numpy(a).reshape(-1), np.asarray(values).reshape(-1))
    check(f"{label}: VTK's own reader (ParaView's) reads the same triangles and arrays", bool(same))


def check_state(folder, E, nu, model):
    label = folder.rstrip("/").split("/")[-1] + "/solution.vtu"
    path = folder + "/solution.vtu"
    check_format(path, label)
    mesh = meshio.read(path)
    check_vtk(path, mesh, label)
    nodes = columns(folder + "/nodes.dat")
    contact = columns(folder + "/contact.dat")
    summary = dict(line.split()[:2] for line in open(folder + "/summary.dat") if not line.startswith("#"))
    tri = mesh.cells_dict.get("triangle")
    friction = contact.shape[1] == 8
    check(f"{label}: {len(mesh.points)} points, the rows of nodes.dat; "
          f"{0 if tri is None else len(tri)} triangles, as summary.dat",
          len(mesh.points) == len(nodes) and tri is not None
          and len(tri) == int(summary["triangles"]) and len(mesh.cells) == 1)
    want_p = {"displacement", "gap", "pressure", "contact_node"} | ({"tangential_force"} if friction else set())
    want_c = {"sigma11", "sigma22", "sigma12", "sigma33", "von_mises"}
    check(f"{label}: point arrays {sorted(mesh.point_data)}, cell arrays {sorted(mesh.cell_data)}",
          set(mesh.point_data) == want_p and set(mesh.cell_data) == want_c)
    if tri is None or set(mesh.point_data) != want_p or set(mesh.cell_data) != want_c:
        return
    u = point_array(mesh, "displacement")
    check(f"{label}: the points are x1, x2 of nodes.dat (x3 = 0)",
          close(mesh.points[:, :2], nodes[:, 3:5], 1e-14) and not mesh.points[:, 2].any())
    check(f"{label}: the displacement is u1, u2 of nodes.dat (u3 = 0)",
          u.shape[1] == 3 and close(u[:, :2], nodes[:, 5:7], 1e-14) and not u[:, 2].any())
    check_contact(mesh, contact, friction, label)
    check_stress(mesh, tri, u, E, nu, model, label)


def check_contact(mesh, contact, friction, label):
    on = point_array(mesh, "contact_node")[:, 0] == 1
    gap, p = point_array(mesh, "gap")[:, 0], point_array(mesh, "pressure")[:, 0]
    order = np.argsort(mesh.points[on, 0])               # contact.dat is by x1
    check(f"{label}: contact_node marks {on.sum()} nodes, the rows of contact.dat, at its x1",
          on.sum() == len(contact) and close(mesh.points[on, 0][order], contact[:, 0], 1e-14))
    if on.sum() != len(contact):
        return
    check(f"{label}: gap and pressure at the contact nodes are those of contact.dat",
          close(gap[on][order], contact[:, 3], 1e-13) and close(p[on][order], contact[:, 5], 1e-13))
    check(f"{label}: gap and pressure are 0 off the contact nodes, finite everywhere",
          not gap[~on].any() and not p[~on].any() and np.isfinite(gap).all() and np.isfinite(p).all())
    if friction:
        t = point_array(mesh, "tangential_force")[:, 0]
        check(f"{label}: tangential_force at the contact nodes is Tt of contact.dat, 0 elsewhere",
              close(t[on][order], contact[:, 7], 1e-13) and not t[~on].any())


def check_stress(mesh, tri, u, E, nu, model, label):
    got = np.column_stack([cell_array(mesh, n) for n in
                           ("sigma11", "sigma22", "sigma12", "sigma33", "von_mises")])
    want = stresses(mesh.points, tri, u, E, nu, model)
    vm = got[:, 4]
    check(f"{label}: von Mises finite and >= 0 on every triangle (max {vm.max():.4g} Pa)",
          np.isfinite(got).all() and (vm >= 0).all())
    worst = int(np.argmax(vm))
    check(f"{label}: the stress of triangle {worst} (the largest von Mises) recomputed here from "
          f"the displacement, {model}: {got[worst, 4]:.10g} Pa",
          np.allclose(got[worst], want[worst], rtol=1e-9, atol=1e-9 * vm.max()))
    check(f"{label}: the stress of all {len(tri)} triangles recomputed to 1e-9 of the largest",
          np.all(np.abs(got - want) <= 1e-9 * np.abs(want).max()))
    s33 = nu * (got[:, 0] + got[:, 1]) if model == "plane_strain" else 0 * vm
    check(f"{label}: sigma33 is {'nu (sigma11 + sigma22)' if model == 'plane_strain' else '0'} ({model})",
          np.allclose(got[:, 3], s33, rtol=0, atol=1e-12 * vm.max()))


# ---- iterates.pvd and iterates/ against history.dat and iterates.dat ------
def check_pvd(folder, E, nu, model):
    label = folder.rstrip("/").split("/")[-1] + "/iterates.pvd"
    root = ET.parse(folder + "/iterates.pvd").getroot()
    sets = root.findall("./Collection/DataSet")
    iteration = [int(row[0]) for row in columns(folder + "/history.dat")]
    steps = [int(d.get("timestep")) for d in sets]
    check(f"{label}: a VTK collection of {len(sets)} data sets whose time steps are the "
          f"iterations of history.dat", root.get("type") == "Collection" and steps == iteration)
    names = [d.get("file") for d in sets]
    listed = sorted(os.listdir(folder + "/iterates"))
    check(f"{label}: every file is iterates/iterate-NNNN.vtu of its iteration, is there, "
          f"and iterates/ holds no other ({len(listed)} files)",
          names == [f"iterates/iterate-{k:04d}.vtu" for k in steps]
          and listed == sorted(n.split("/")[1] for n in names))
    if names != [f"iterates/iterate-{k:04d}.vtu" for k in steps] or not names:
        return
    design = columns(folder + "/iterates.dat")
    final = meshio.read(folder + "/final/solution.vtu")
    meshes = [meshio.read(folder + "/" + n) for n in names]
    ncol = int(design[:, 1].max()) + 1
    same = all(len(m.points) == len(final.points) and len(m.cells[0].data) == len(final.cells[0].data)
               and set(m.point_data) == set(final.point_data) and set(m.cell_data) == set(final.cell_data)
               and np.array_equal(m.cells[0].data, final.cells[0].data) for m in meshes)
    at = all(np.array_equal(m.points[:ncol, 1], design[design[:, 0] == k, 3]) for m, k in zip(meshes, steps))
    check(f"{label}: all {len(meshes)} iterates load, with the triangles and arrays of "
          f"final/solution.vtu, and the contact nodes of each at its design in iterates.dat", same and at)
    check(f"{label}: iteration {steps[0]} is initial/solution.vtu, byte for byte",
          open(folder + "/" + names[0], "rb").read() == open(folder + "/initial/solution.vtu", "rb").read())
    last = meshes[-1]
    check(f"{label}: iteration {steps[-1]}, the last, is the state of final/solution.vtu "
          f"(points, displacement, stress to 1e-9)",
          close(last.points, final.points, 1e-15)
          and close(point_array(last, "displacement"), point_array(final, "displacement"), 1e-9)
          and close(cell_array(last, "von_mises"), cell_array(final, "von_mises"), 1e-9))
    check_vtk(folder + "/" + names[len(names) // 2], meshes[len(names) // 2],
              f"{label}: {names[len(names) // 2]}")
    for k in (0, len(meshes) - 1):
        check_stress(meshes[k], meshes[k].cells_dict["triangle"], point_array(meshes[k], "displacement"),
                     E, nu, model, f"{label}: {names[k]}")


if __name__ == "__main__":
    if len(sys.argv) == 6 and sys.argv[1] in ("state", "pvd"):
        (check_state if sys.argv[1] == "state" else check_pvd)(
            sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), sys.argv[5])
    else:
        print("FAIL - usage: paraview.py state DIR E NU MODEL | pvd DIR")
        failures += 1
    sys.exit(1 if failures else 0)
