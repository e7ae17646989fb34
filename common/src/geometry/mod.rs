//! Shapes, bounding boxes, the BVH and robust secondary rays. (Being written.)
