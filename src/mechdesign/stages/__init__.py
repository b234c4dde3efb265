"""Analysis stages shared by every machine (flywheel, …): each turns earlier results into
one frozen result. Machines compose them; nothing here names a machine."""
