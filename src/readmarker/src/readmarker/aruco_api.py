"""OpenCV's ArUco calls across its two APIs: 4.7 replaced DetectorParameters_create, drawMarker
and detectMarkers(image, dictionary, parameters) with DetectorParameters(), generateImageMarker
and ArucoDetector. Debian 12 has 4.6 (the old ones); newer systems have only the new."""
import cv2

NEW_API = hasattr(cv2.aruco, 'ArucoDetector')


def detector_parameters():
    return cv2.aruco.DetectorParameters() if NEW_API else cv2.aruco.DetectorParameters_create()


def detect_markers(grey, dictionary, parameters):
    """(corners, ids) as detectMarkers gives them."""
    if NEW_API:
        corners, ids, _ = cv2.aruco.ArucoDetector(dictionary, parameters).detectMarkers(grey)
    else:
        corners, ids, _ = cv2.aruco.detectMarkers(grey, dictionary, parameters=parameters)
    return corners, ids


def marker_image(dictionary, marker_id, size):
    if NEW_API:
        return cv2.aruco.generateImageMarker(dictionary, marker_id, size)
    return cv2.aruco.drawMarker(dictionary, marker_id, size)
