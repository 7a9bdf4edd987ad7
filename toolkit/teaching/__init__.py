"""What the course around the library uses: the notebooks' helpers, running notebooks headless, a
JupyterLab in a browser, grading assignments, and the course website.

Reading order:

1. :mod:`toolkit.teaching.notebook` — quick mode and the trained-model cache the notebooks share;
   :mod:`toolkit.teaching.recorded` — the tables of ``docs/results.md``, read where a notebook quotes them;
2. :mod:`toolkit.teaching.notebook_runner` — run and time notebooks without a browser;
3. :mod:`toolkit.teaching.lab_browser` — JupyterLab in headless Chromium, screenshots of rendered notebooks;
4. :mod:`toolkit.teaching.grading` — otter-grader assignments: build, grade, report;
5. :mod:`toolkit.teaching.handout` — the students' tree without solutions, and the check for leaked ones;
6. :mod:`toolkit.teaching.site` — the course website (mkdocs), built from all of the above;
   :mod:`toolkit.teaching.site_hooks` — what mkdocs runs on each page: links, notebook headings, docstring roles.
"""
