"""Pages and tables rendered from Jinja2 templates, HTML escaped by Jinja2 itself.

The package's templates are in ``turntable/templates``; the workflow and the site keep
theirs beside them and pass their folder.  A template whose name ends in ``.html.j2`` is
escaped automatically (autoescape): a value is shown as text, whatever it holds, unless it
is `markupsafe.Markup` (HTML made on purpose, such as `turntable.claims.report.html_math`).
"""

from __future__ import annotations

import os
from typing import Any


def render(template: str, folder: str | os.PathLike[str] | None = None, /, **context: Any) -> str:
    """Render the template ``template`` with ``context``.

    Parameters
    ----------
    template : str
        File name of the template, e.g. ``claims.html.j2``; ``.html.j2`` is escaped for
        HTML, any other (``.md.j2``) is not.
    folder : str or os.PathLike, optional
        The folder of the template; by default the package's ``turntable/templates``.
    **context
        The template's variables. A variable the template uses and ``context`` lacks is an
        error (`jinja2.StrictUndefined`), not an empty string.

    Returns
    -------
    str
        The rendered text; a template ending in a newline gives a text ending in one.

    See Also
    --------
    jinja2.select_autoescape : Which templates are escaped.
    """
    import jinja2

    loader = (
        jinja2.PackageLoader("turntable", "templates")
        if folder is None
        else jinja2.FileSystemLoader(os.fspath(folder))
    )
    env = jinja2.Environment(
        loader=loader,
        autoescape=jinja2.select_autoescape(enabled_extensions=("html.j2",)),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
    )
    return env.get_template(template).render(**context)


def markup(html: str) -> Any:
    """``html`` marked as safe, inserted into an escaped template as it is."""
    from markupsafe import Markup

    return Markup(html)


def escape(text: Any) -> Any:
    """``text`` escaped for HTML, as an escaped template escapes a value."""
    from markupsafe import escape as _escape

    return _escape(text)
