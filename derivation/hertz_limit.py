def derive(ctx):
    return set()
