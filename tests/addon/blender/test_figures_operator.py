"""The panel's "Render figures": the add-on's own figure script (figures/render_figures.py, shipped
in the package) run on the active mesh in a separate Blender (the same one: its executable, or the
bpy module's Python) into the chosen folder. In background mode the operator waits for the
process; the window's modal polling and Esc are the same Job (tests/addon/unit/test_figures_job.py).
The same from an installed zip, and the refusal before the file browser when the script is
missing: test_installed_figures.py."""
import bpy


def test_figures_of_the_active_mesh(clean_scene, data_dir, tmp_path):
    path = data_dir / "hybrid-base-complex" / "twistcube_s.mesh"
    assert bpy.ops.import_mesh.hbc(filepath=str(path)) == {"FINISHED"}
    out = tmp_path / "figures"
    assert bpy.ops.hbc.render_figures(directory=str(out), engine="cycles", width=48, height=36, samples=1,
                                      wait=True) == {"FINISHED"}
    # Every default panel (a-g: twistcube_s has self-intersecting sheets) and the contact sheet.
    pngs = sorted(p.name for p in out.glob("*.png"))
    assert "twistcube_s_contact.png" in pngs and len(pngs) == 8, pngs
