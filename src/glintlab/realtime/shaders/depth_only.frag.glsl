// Depth-only fragment stage (shadow maps): writes nothing but depth.
void main() {}
