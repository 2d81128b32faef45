//! Secs. 3.2–3.5: abstract sets of gluing data (Def. 3.4.1) and their checkers (issue 3).
