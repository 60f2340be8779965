#!/usr/bin/env python3
"""Independent counts for tests/io/osim_counts_test.cc.

Uses Python's xml.etree (not pugixml, not Sinew's code). Only two textual fixes are applied so a
strict XML parser accepts the files: '::' in element names becomes '__', and a bare '&' becomes
'&amp;'. Counting rules (OpenSim's layouts):
  bodies      = children of BodySet/objects, minus a 3.x body named 'ground'
  joints      = children of JointSet/objects (4.x, 3.05) + children of every Body/Joint (3.x)
  coordinates = Coordinate elements under those joints
  forces      = children of ForceSet/objects
  constraints = children of ConstraintSet/objects
  markers     = children of MarkerSet/objects
Usage: count_osim.py FILE...          (prints one line of counts per file)
       count_osim.py --joints FILE...  (prints "file joint parent_body child_body" lines)
       count_osim.py --frames FILE...  (prints "file joint" + R_PF (9, row-major), p_PF,
                                        R_BM, p_BM: the joint frames in their bodies)

--joints resolves each joint's parent and child BODY independently of Sinew: 3.x joints hang
from `parent_body` into the Body that holds them (swapped when `reverse` is true, as OpenSim's
30514 upgrade does); 3.05 connectors name bodies; 4.x socket paths are resolved against component
paths built from element names (sets as /bodyset, /jointset, ...), relative to the socket's
owner, following PhysicalOffsetFrame socket_parent and a StationDefinedFrame's first station.
"""
import math
import re
import sys
import xml.etree.ElementTree as ET


def load(path):
    text = open(path, 'rb').read().decode('utf-8', 'replace')
    text = re.sub(r'(</?[A-Za-z_][\w.-]*)::', r'\1__', text)
    text = re.sub(r'&(?!(amp|lt|gt|quot|apos|#\d+|#x[0-9a-fA-F]+);)', '&amp;', text)
    return ET.fromstring(text.encode('utf-8'))


def objects(model, set_tag):
    s = model.find(set_tag)
    if s is None:
        return []
    o = s.find('objects')
    return list(o) if o is not None else []


def count(path):
    root = load(path)
    model = root.find('Model')
    bodies = [b for b in objects(model, 'BodySet')]
    joints = objects(model, 'JointSet')
    for b in bodies:
        w = b.find('Joint')
        if w is not None:
            joints += list(w)
    n_bodies = len([b for b in bodies if not (b.get('name') == 'ground' and model.find('Ground') is None)])
    coords = sum(len(j.findall('.//Coordinate')) for j in joints)
    return dict(version=int(root.get('Version')), bodies=n_bodies, joints=len(joints),
                coordinates=coords, forces=len(objects(model, 'ForceSet')),
                constraints=len(objects(model, 'ConstraintSet')),
                markers=len(objects(model, 'MarkerSet')))


def component_paths(model):
    """Maps absolute component path -> element for every named element below the model."""
    paths = {}

    def walk(elem, prefix):
        for child in elem:
            tag = child.tag
            if tag.endswith('Set'):
                seg = tag.lower()
            elif tag == 'Ground':
                seg = 'ground'
            elif child.get('name') is not None and child.get('name') != '':
                seg = child.get('name')
            else:
                seg = None
            path = prefix + '/' + seg if seg else prefix
            if seg and not tag.endswith('Set'):
                paths.setdefault(path, child)
            walk(child, path)
    walk(model, '')
    return paths


def join(owner, rel):
    parts = [] if rel.startswith('/') else [p for p in owner.split('/') if p]
    for seg in rel.split('/'):
        if seg in ('', '.'):
            continue
        if seg == '..':
            parts.pop()
        else:
            parts.append(seg)
    return '/' + '/'.join(parts)


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def mat_vec(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]


def rotation_xyz(angles):
    """Body-fixed X-Y-Z: R = Rx(a) Ry(b) Rz(c)."""
    def rx(t):
        c, s = math.cos(t), math.sin(t)
        return [[1, 0, 0], [0, c, -s], [0, s, c]]

    def ry(t):
        c, s = math.cos(t), math.sin(t)
        return [[c, 0, s], [0, 1, 0], [-s, 0, c]]

    def rz(t):
        c, s = math.cos(t), math.sin(t)
        return [[c, -s, 0], [s, c, 0], [0, 0, 1]]
    return mat_mul(mat_mul(rx(angles[0]), ry(angles[1])), rz(angles[2]))


IDENTITY = ([[1, 0, 0], [0, 1, 0], [0, 0, 1]], [0.0, 0.0, 0.0])


def compose(x_ab, x_bc):
    r_ab, p_ab = x_ab
    r_bc, p_bc = x_bc
    return mat_mul(r_ab, r_bc), [a + b for a, b in zip(mat_vec(r_ab, p_bc), p_ab)]


def vec(elem, tag):
    node = elem.find(tag)
    if node is None or node.text is None or not node.text.strip():
        return [0.0, 0.0, 0.0]
    return [float(t) for t in node.text.split()]


def offset(elem, ori, loc):
    return rotation_xyz(vec(elem, ori)), vec(elem, loc)


def frame_of(paths, owner, rel):
    """(body name, X_BF) of the frame a socket names."""
    path = join(owner, rel.strip())
    elem = paths[path]
    if elem.tag in ('Body', 'Ground'):
        return ('ground' if elem.tag == 'Ground' else elem.get('name')), IDENTITY
    if elem.tag == 'PhysicalOffsetFrame':
        body, x_bp = frame_of(paths, path, elem.find('socket_parent').text)
        return body, compose(x_bp, offset(elem, 'orientation', 'translation'))
    raise ValueError('frame kind not handled here: ' + path)


def body_of(paths, owner, rel):
    path = join(owner, rel.strip())
    elem = paths[path]
    if elem.tag in ('Body', 'Ground'):
        return 'ground' if elem.tag == 'Ground' else elem.get('name')
    if elem.tag == 'PhysicalOffsetFrame':
        return body_of(paths, path, elem.find('socket_parent').text)
    if elem.tag == 'StationDefinedFrame':
        station_path = join(path, elem.find('socket_point_a').text.strip())
        station = paths[station_path]
        return body_of(paths, station_path, station.find('socket_parent_frame').text)
    raise ValueError('not a frame: ' + path)


def joint_bodies(path):
    model = load(path).find('Model')
    rows = []
    for j in objects(model, 'JointSet'):
        if j.find('socket_parent_frame') is not None:
            paths = component_paths(model)
            own = '/jointset/' + j.get('name')
            rows.append((j.get('name'), body_of(paths, own, j.find('socket_parent_frame').text),
                         body_of(paths, own, j.find('socket_child_frame').text)))
        else:
            names = {c.get('name'): c.find('connectee_name').text.strip().split('/')[-1]
                     for c in j.find('connectors')}
            rows.append((j.get('name'), names['parent_body'], names['child_body']))
    for b in objects(model, 'BodySet'):
        w = b.find('Joint')
        for j in (list(w) if w is not None else []):
            parent, child = j.find('parent_body').text.strip(), b.get('name')
            rev = j.find('reverse')
            if rev is not None and rev.text.strip() == 'true':
                parent, child = child, parent
            rows.append((j.get('name') or '', parent, child))
    return rows


def joint_frames(path):
    """(joint, X_PF, X_BM) for joints whose frames are offsets (no station-defined frames)."""
    model = load(path).find('Model')
    rows = []
    for j in objects(model, 'JointSet'):
        if j.find('socket_parent_frame') is not None:
            paths = component_paths(model)
            own = '/jointset/' + j.get('name')
            try:
                x_pf = frame_of(paths, own, j.find('socket_parent_frame').text)[1]
                x_bm = frame_of(paths, own, j.find('socket_child_frame').text)[1]
            except ValueError:
                continue
        else:
            x_pf = offset(j, 'orientation_in_parent', 'location_in_parent')
            x_bm = offset(j, 'orientation_in_child', 'location_in_child')
        rows.append((j.get('name'), x_pf, x_bm))
    for b in objects(model, 'BodySet'):
        w = b.find('Joint')
        for j in (list(w) if w is not None else []):
            x_pf = offset(j, 'orientation_in_parent', 'location_in_parent')
            x_bm = offset(j, 'orientation', 'location')
            rev = j.find('reverse')
            if rev is not None and rev.text.strip() == 'true':
                x_pf, x_bm = x_bm, x_pf
            rows.append((j.get('name') or '-', x_pf, x_bm))
    return rows


if __name__ == '__main__' and sys.argv[1:2] == ['--frames']:
    for p in sys.argv[2:]:
        for name, x_pf, x_bm in joint_frames(p):
            numbers = [x for row in x_pf[0] for x in row] + x_pf[1] + \
                [x for row in x_bm[0] for x in row] + x_bm[1]
            print(p.split('tests/data/')[-1], name, ' '.join('%.17g' % x for x in numbers))
elif __name__ == '__main__' and sys.argv[1:2] == ['--joints']:
    for p in sys.argv[2:]:
        for name, parent, child in joint_bodies(p):
            print(p.split('tests/data/')[-1], name or '-', parent, child)
elif __name__ == '__main__':
    for p in sys.argv[1:]:
        c = count(p)
        print('{"%s", %d, %d, %d, %d, %d, %d, %d},' % (
            p.split('tests/data/')[-1], c['version'], c['bodies'], c['joints'], c['coordinates'],
            c['forces'], c['constraints'], c['markers']))
