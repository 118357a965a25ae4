"""The exceptions matc raises for bad input, with the located diagnostics attached."""


class MaterialError(ValueError):
    """A material, document or batch input has errors.

    ``str(error)`` is what the ``matc`` command prints, one diagnostic per line
    (``path:line:column: error: field: message; allowed``); ``error.diagnostics``
    holds them as :class:`matc.Diagnostic` values (``path``, ``line``, ``column``,
    ``severity``, ``field``, ``message``, ``allowed``).
    """

    def __init__(self, message, diagnostics=()):
        super().__init__(message)
        self.diagnostics = list(diagnostics)

    @property
    def errors(self):
        """The diagnostics of severity ``error``."""
        return [d for d in self.diagnostics if d.severity == "error"]


class BatchError(MaterialError):
    """A batch compile had failures; ``error.result`` is the :class:`matc.BatchResult`
    (what was compiled and written before, or around, the failures)."""

    def __init__(self, message, diagnostics=(), result=None):
        super().__init__(message, diagnostics)
        self.result = result
