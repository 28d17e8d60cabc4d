% Van Roy benchmark 'browse', written for robocram from the benchmark's published
% description (Gabriel's "browse": build a database of units with property lists,
% shuffle it with a seeded generator, then match patterns with segment variables
% star(X) against every pattern stored in every unit). Not a copy of any distributed
% version; the input patterns are the benchmark's published data. Entry point: top/0.

top :-
    browse_units(100, 10, 4,
        [[a,a,a,b,b,b,b,a,a,a,a,a,b,b,a,a,a],
         [a,a,b,b,b,b,a,a,[a,a],[b,b]],
         [a,a,a,b,[b,a],b,a,b,a]], Units),
    browse_shuffle(Units, 21, Shuffled), !,
    browse_investigate(Shuffled,
        [[star(SA),B,star(SB),B,a,star(SA),a,star(SB),star(SA)],
         [star(SA),star(SB),star(SB),star(SA),[star(SA)],[star(SB)]],
         [_,_,star(_),[b,a],star(_),_,_]]).

% Unit I has I mod M dummy properties, its patterns, then the rest of M dummies.
browse_units(N, M, NPats, Pats, Units) :- browse_units(0, N, M, NPats, Pats, Units).
browse_units(N, N, _, _, _, []) :- !.
browse_units(I, N, M, NPats, Pats, [Unit|Units]) :-
    Before is I mod M, After is M - Before,
    length(Pats, L), Start is I mod L,
    browse_cycle(NPats, Start, Pats, Mine),
    browse_dummies(After, [], Tail),
    browse_dummies(Before, [pattern(Mine)|Tail], Unit),
    I1 is I + 1, browse_units(I1, N, M, NPats, Pats, Units).

browse_dummies(0, L, L) :- !.
browse_dummies(N, L, [dummy(N)|R]) :- N1 is N - 1, browse_dummies(N1, L, R).

% K patterns taken in turn from Pats, starting at index Start, wrapping around
browse_cycle(0, _, _, []) :- !.
browse_cycle(K, Start, Pats, [P|Ps]) :-
    nth0(Start, Pats, P), length(Pats, L), Next is (Start + 1) mod L,
    K1 is K - 1, browse_cycle(K1, Next, Pats, Ps).

% take the element at Seed mod length out, next seed (Seed * 17) mod 251
browse_shuffle([], _, []) :- !.
browse_shuffle(L, Seed, [X|R]) :-
    length(L, N), I is Seed mod N, browse_take(I, L, X, Rest),
    Seed1 is (Seed * 17) mod 251, browse_shuffle(Rest, Seed1, R).

browse_take(0, [X|L], X, L) :- !.
browse_take(I, [Y|L], X, [Y|R]) :- I1 is I - 1, browse_take(I1, L, X, R).

browse_investigate(Units, Queries) :-
    member(Unit, Units), member(pattern(Data), Unit), member(D, Data),
    member(Q, Queries), browse_match(Q, D), fail.
browse_investigate(_, _).

browse_match([], []).
browse_match([P|Ps], Ds) :-
    nonvar(P), P = star(Seg), !, browse_append(Seg, Rest, Ds), browse_match(Ps, Rest).
browse_match([P|Ps], [D|Ds]) :-
    ( var(P) -> P = D ; atom(D) -> P = D ; browse_match(P, D) ),
    browse_match(Ps, Ds).

browse_append([], L, L).
browse_append([X|L1], L2, [X|L3]) :- browse_append(L1, L2, L3).
