# Expansion range of compare_distance (bounds.md#expansion-range): the absolute tree of
#   (px - cx)^2 + (py - cy)^2 - (qx - cx)^2 - (qy - cy)^2,
# homogeneous of degree 2. See range_orient.g for how K becomes distance_max_log.
{ |px| in [0, 1] /\ |py| in [0, 1] /\ |qx| in [0, 1] /\ |qy| in [0, 1] /\ |cx| in [0, 1] /\ |cy| in [0, 1]
  -> (|px| + |cx|) * (|px| + |cx|) + (|py| + |cy|) * (|py| + |cy|)
     + (|qx| + |cx|) * (|qx| + |cx|) + (|qy| + |cy|) * (|qy| + |cy|) in ? }
