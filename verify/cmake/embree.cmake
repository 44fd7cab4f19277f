# Owned by the embree oracle work; filled in by it.
