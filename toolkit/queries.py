"""``toolkit.queries``: the paper's query sets and runs over them, kept at this name for code
written against it; the code is in :mod:`toolkit.planning.queries`."""

from toolkit.planning.queries import (
    Query,
    compare_prediction,
    default_options,
    make_queries,
    one_thread,
    query_pairs,
    run_interleaved,
    run_queries,
    solve_query,
    summarize,
)

__all__ = [
    "Query",
    "compare_prediction",
    "default_options",
    "make_queries",
    "one_thread",
    "query_pairs",
    "run_interleaved",
    "run_queries",
    "solve_query",
    "summarize",
]
