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

--joints resolves each joint's parent and child BODY independently of Sinew: 3.x joints hang
from `parent_body` into the Body that holds them (swapped when `reverse` is true, as OpenSim's
30514 upgrade does); 3.05 connectors name bodies; 4.x socket paths are resolved against component
paths built from element names (sets as /bodyset, /jointset, ...), relative to the socket's
owner, following PhysicalOffsetFrame socket_parent and a StationDefinedFrame's first station.
"""
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


if __name__ == '__main__' and sys.argv[1:2] == ['--joints']:
    for p in sys.argv[2:]:
        for name, parent, child in joint_bodies(p):
            print(p.split('tests/data/')[-1], name or '-', parent, child)
elif __name__ == '__main__':
    for p in sys.argv[1:]:
        c = count(p)
        print('{"%s", %d, %d, %d, %d, %d, %d, %d},' % (
            p.split('tests/data/')[-1], c['version'], c['bodies'], c['joints'], c['coordinates'],
            c['forces'], c['constraints'], c['markers']))
