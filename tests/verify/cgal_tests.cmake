# Owned by the cgal oracle work; filled in by it.
