using System;
using System.Numerics;
using Fulcrum.Mathematics;

namespace Fulcrum.Dynamics
{
    /// <summary>
    /// The forest of body and joint nodes: which joints close no loop (union-find), and the
    /// order, leaves first, in which the factorisation eliminates them.
    /// </summary>
    internal sealed partial class JointTreeSolver
    {
        // A dynamic body with a mass and an invertible inertia; kinematic and static ones are
        // not nodes (false); a locked dynamic body, or one whose inertia cannot be inverted,
        // takes its joints out of the block (locked).
        static bool Treeable(in SolverBody body, int index, out bool locked)
        {
            locked = false;
            if (index == 0 || body.IsDynamic == 0) return false;
            if (body.IsDynamic != 1 || !(body.InverseMass > 0)) { locked = true; return false; }
            Mat3 ii = body.InverseInertia;
            float det = Vector3.Dot(ii.C0, Vector3.Cross(ii.C1, ii.C2));
            if (!(det > 0) || !float.IsFinite(det)) { locked = true; return false; }
            return true;
        }

        int Find(int i)
        {
            while (_find[i] != i)
            {
                _find[i] = _find[_find[i]];
                i = _find[i];
            }
            return i;
        }

        // Nodes, adjacency, a root per tree and the elimination order (reverse pre-order: every
        // node after all of its descendants).
        void Arrange(SolverBody[] bodies, JointData[] data)
        {
            int capacity = 3 * _directCount + 1;
            Grow(ref _body, capacity);
            Grow(ref _joint, capacity);
            Grow(ref _parent, capacity);
            Grow(ref _order, capacity);
            Grow(ref _nodeA, capacity);
            Grow(ref _nodeB, capacity);
            Grow(ref _stack, capacity);
            Grow(ref _first, capacity);
            Grow(ref _dim, capacity);
            Grow(ref _next, 2 * capacity);
            if (_armA.Length < capacity)
            {
                _armA = new Vector3[capacity];
                _armB = new Vector3[capacity];
                _gap = new Vector3[capacity];
                _scale = new Vector2[Stride * capacity];
                _rows = new JointKind[capacity];
                _axes = new Vector3[3 * capacity];
                _error = new Vector3[capacity];
                _leaf = new bool[capacity];
                _free = new bool[capacity];
                _tilt = new byte[capacity];
                _released = new byte[capacity];
                _subtreeMass = new float[capacity];
            }
            if (_dinv.Length < Block * capacity)
            {
                _dinv = new double[Block * capacity];
                _h = new double[Block * capacity];
                _l = new double[Block * capacity];
                _x = new double[Stride * capacity];
            }
            int n = 0;
            for (int k = 0; k < _directCount; k++)
            {
                ref JointData j = ref data[_direct[k]];
                int jn = n++;
                _body[jn] = -1;
                _joint[jn] = _direct[k];
                bool cone = j.Kind == JointKind.ConeTwist && (j.DirectLimit & (ConeRow | TwistLowerRow | TwistUpperRow)) != 0;
                _rows[jn] = j.Kind == JointKind.Distance || j.Kind == JointKind.Prismatic || j.DirectRotation || cone ? j.Kind : JointKind.Ball;
                _dim[jn] = j.Kind == JointKind.Distance ? 3 : j.Kind == JointKind.Prismatic ? (j.DirectLimit != 0 ? 6 : 5)
                    : j.DirectRotation ? (j.Kind == JointKind.Fixed || j.DirectLimit != 0 ? 6 : 5) : cone ? 5 : 3;
                _nodeA[jn] = BodyNode(bodies, j.SolverA, ref n);
                _nodeB[jn] = BodyNode(bodies, j.SolverB, ref n);
            }
            _nodes = n;
            for (int i = 0; i < n; i++)
            {
                _free[i] = false;
                _released[i] = 0;
            }
            // Adjacency of body nodes: a linked list of (joint node) edges per body node.
            for (int i = 0; i < n; i++) _parent[i] = -2;
            for (int i = 0; i < n; i++) _first[i] = -1;
            for (int i = 0; i < n; i++)
            {
                if (_joint[i] < 0) continue;
                Link(_nodeA[i], i, 0);
                Link(_nodeB[i], i, 1);
            }
            int visited = 0;
            // Anchored joints first, as roots; then the bodies of trees without one.
            for (int pass = 0; pass < 2; pass++)
                for (int i = 0; i < n; i++)
                {
                    if (_parent[i] != -2) continue;
                    bool anchoredJoint = _joint[i] >= 0 && (_nodeA[i] < 0 || _nodeB[i] < 0);
                    if (pass == 0 ? !anchoredJoint : _joint[i] >= 0) continue;
                    int first = visited;
                    visited = Walk(i, visited);
                    GateLimits(bodies, data, first, visited);
                }
            // Reverse pre-order.
            for (int i = 0; i < visited / 2; i++) (_order[i], _order[visited - 1 - i]) = (_order[visited - 1 - i], _order[i]);
            // Bodies with no children in their tree: D = M, and nothing to carry in the solves.
            for (int i = 0; i < n; i++) _leaf[i] = _joint[i] < 0;
            for (int i = 0; i < n; i++)
                if (_parent[i] >= 0) _leaf[_parent[i]] = false;
            _stale = true;
        }

        // The node of a dynamic body (made on first use); -1 for a static or kinematic one.
        int BodyNode(SolverBody[] bodies, int solverBody, ref int n)
        {
            if (solverBody == 0 || bodies[solverBody].IsDynamic != 1) return -1;
            int node = _bodyNode[solverBody];
            if (node >= 0) return node;
            _body[n] = solverBody;
            _joint[n] = -1;
            _dim[n] = 6;
            _bodyNode[solverBody] = n;
            return n++;
        }

        void Link(int bodyNode, int jointNode, int side)
        {
            if (bodyNode < 0) return;
            int e = 2 * jointNode + side;
            _next[e] = _first[bodyNode];
            _first[bodyNode] = e;
        }

        // Depth-first from root, writing the pre-order into _order from position at.
        int Walk(int root, int at)
        {
            int top = 0;
            _stack[top++] = root;
            _parent[root] = -1;
            while (top > 0)
            {
                int node = _stack[--top];
                _order[at++] = node;
                if (_joint[node] >= 0)
                {
                    Push(_nodeA[node], node, ref top);
                    Push(_nodeB[node], node, ref top);
                }
                else
                    for (int e = _first[node]; e >= 0; e = _next[e]) Push(e >> 1, node, ref top);
            }
            return at;
        }

        void Push(int node, int parent, ref int top)
        {
            if (node < 0 || _parent[node] != -2) return;
            _parent[node] = parent;
            _stack[top++] = node;
        }
    }
}
