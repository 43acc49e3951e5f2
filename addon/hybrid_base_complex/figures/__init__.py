"""The paper-style figures (`render_figures.py`), shipped with the add-on so that its *Figures*
button works wherever the add-on is installed: `plan` (no bpy: options, panels, camera, legend
layout) and `compose` (numpy pixel work) are tested with plain Python; `render` (the studio scene,
built with the add-on's own layers) and `script` (the panels and sheets written) run in Blender;
`render_figures.py` is the file Blender runs. Nothing of the add-on imports this package: the panel
starts it in a second Blender (plan/figures_job.py)."""
