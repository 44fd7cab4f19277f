# Owned by the osmesa oracle work; filled in by it.
