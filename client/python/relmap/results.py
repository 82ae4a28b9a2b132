"""The answers of ComputeMaps and ClassifyFeatures as numpy arrays, the proto kept."""

from __future__ import annotations

import dataclasses
from typing import Optional

import numpy as np

from relmap.v1 import relevance_service_pb2 as pb


@dataclasses.dataclass(frozen=True)
class Session:
    """A session as the client holds it: its id and bearer token (shown once, at
    creation), and the configuration it was created with, defaults filled in."""

    id: str
    token: str
    config: pb.SessionConfig = dataclasses.field(default_factory=pb.SessionConfig, repr=False)


@dataclasses.dataclass(frozen=True)
class Maps:
    """A mapped frame: per supervoxel (index = supervoxel id) its relevance P(moveable)
    and choice probability, centroid and mean normal (camera frame, metres), point
    count and object (supervoxels with the same value lie on one object, which a push
    moves whole: 0, 1, ... in the order of their lowest id); the drawn target (None when no supervoxel has usable features); per point of
    the cloud its supervoxel id or -1 (None when omitted); the 48 features per
    supervoxel when asked for (None otherwise)."""

    frame_id: int
    target: Optional[int]
    relevance: np.ndarray
    choice: np.ndarray
    centroids: np.ndarray
    normals: np.ndarray
    point_counts: np.ndarray
    objects: np.ndarray
    point_labels: Optional[np.ndarray]
    features: Optional[np.ndarray]
    unusable_supervoxels: int
    response: pb.ComputeMapsResponse = dataclasses.field(repr=False)

    @classmethod
    def from_response(cls, response: pb.ComputeMapsResponse, with_labels: bool,
                      with_features: bool) -> "Maps":
        voxels = response.supervoxels
        features = None
        if with_features:
            features = np.array([list(v.features) for v in voxels], dtype=np.float64)
            features = features.reshape(len(voxels), -1)
        return cls(
            frame_id=response.frame_id,
            target=(response.target_supervoxel_id
                    if response.HasField("target_supervoxel_id") else None),
            relevance=np.fromiter((v.relevance for v in voxels), np.float64, len(voxels)),
            choice=np.fromiter((v.choice for v in voxels), np.float64, len(voxels)),
            centroids=np.array([(v.centroid.x, v.centroid.y, v.centroid.z) for v in voxels],
                               dtype=np.float32).reshape(-1, 3),
            normals=np.array([(v.normal.x, v.normal.y, v.normal.z) for v in voxels],
                             dtype=np.float32).reshape(-1, 3),
            point_counts=np.fromiter((v.point_count for v in voxels), np.uint32, len(voxels)),
            objects=np.fromiter((v.object for v in voxels), np.uint32, len(voxels)),
            point_labels=(np.array(response.point_labels, dtype=np.int32)
                          if with_labels else None),
            features=features,
            unusable_supervoxels=response.unusable_supervoxels,
            response=response,
        )


@dataclasses.dataclass(frozen=True)
class Classification:
    """ClassifyFeatures' answer: per vector, in request order, P(moveable) and the
    choice map over the vectors (sums to 1)."""

    relevance: np.ndarray
    choice: np.ndarray
