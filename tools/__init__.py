"""The course's build tools, for whoever maintains the course: not part of the installed library.

``pip install`` ships only ``toolkit/`` (pyproject's ``packages.find``); these modules run from the
repository root (``python -m tools.site --out site``, ``make site``, ``make handout``) and may import
anything of ``toolkit`` and the dev extras (mkdocs, nbclient, Playwright), while ``toolkit`` never
imports them. A student's notebooks need none of them: their helpers stay in :mod:`toolkit.teaching`.

Reading order:

1. :mod:`tools.notebook_runner` — run and time notebooks without a browser;
2. :mod:`tools.lab_browser` — JupyterLab in headless Chromium, screenshots of rendered notebooks;
3. :mod:`tools.handout` — the students' tree without solutions, and the check for leaked ones;
4. :mod:`tools.site` — the course website (mkdocs), built from all of the above;
   :mod:`tools.site_hooks` — what mkdocs runs on each page: links, notebook headings, docstring roles.
"""
