"""numpy, imported on first use (brief layer, shipped catalogues): validating a brief (`mechdesign check`) needs no numpy
(its import is a quarter of the command's time); converting a brief to SI does."""
from __future__ import annotations


class _LazyNumpy:
    def __getattr__(self, name: str):
        import numpy

        return getattr(numpy, name)


np = _LazyNumpy()
