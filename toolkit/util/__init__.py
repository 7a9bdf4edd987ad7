"""What every layer uses and none is about the paper: the bottom of the toolkit, importing nothing of it.

- :mod:`toolkit.util.ragged` — index arithmetic for batches of items of different counts;
- :mod:`toolkit.util.outputs` — output folders checked before work, JSON written atomically;
- :mod:`toolkit.util.threads` — how many threads torch and numpy use (one, by default);
- :mod:`toolkit.util.registry` — named registries (samplers, presets, scenarios): bind and look up;
- :mod:`toolkit.util.plugins` — importing a module of yours that registers a sampler, preset or scenario;
- :mod:`toolkit.util.verdicts` — a ratio's verdict against a tie band ("saves", "network cheaper", "can't tell").
"""
