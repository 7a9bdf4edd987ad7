"""What the course's notebooks and graders use from the library: the notebooks' helpers and grading assignments.

The tools that build the course (running notebooks headless, JupyterLab in a browser, the students'
handout, the website) are not installed with the library: they live in the repository's ``tools/``.

Reading order:

1. :mod:`toolkit.teaching.notebook` — quick mode and the trained-model cache the notebooks share;
   :mod:`toolkit.teaching.recorded` — the tables of ``docs/results.md``, read where a notebook quotes them;
   :mod:`toolkit.teaching.gpu_record` — the GPU figures of ``docs/gpu.md``, or that they are not yet measured;
   :mod:`toolkit.teaching.findings` — the sentences a chapter prints from what it has just measured;
2. :mod:`toolkit.teaching.grading` — otter-grader assignments: build, grade, report (``toolkit grade``).
"""
