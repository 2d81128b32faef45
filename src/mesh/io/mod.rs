//! Mesh readers and writers (OFF, OBJ, PLY). Being written in issue 2 by the readers work.
